"""Means and standard errors shared by the analyses."""
import numpy as np
from scipy import stats


def standard_error(samples, axis=0):
    """Standard error of the mean from the scatter of the samples along axis (nan with fewer
    than two)."""
    samples = np.asarray(samples, dtype=float)
    if samples.shape[axis] < 2:
        return np.full(np.delete(samples.shape, axis), np.nan)[()]
    return stats.sem(samples, axis=axis, ddof=1)


def batch_means(values, batches, keep='last'):
    """Means of `batches` contiguous batches of equal length. The rows that do not fill a batch
    are left out at the start (keep='last', the end of a run is the best equilibrated) or at the
    end (keep='first')."""
    values = np.asarray(values, dtype=float)
    usable = len(values) - len(values) % batches
    kept = values[len(values) - usable:] if keep == 'last' else values[:usable]
    return kept.reshape(batches, -1).mean(axis=1)

#!/usr/bin/python3
"""Viscosity from a reverse-Poiseuille profile written by validation/implicit/in.reverse_poiseuille.

Usage: python/viscosity_fit.py PROFILE --force G [--box L] [--density N]
Fits u(z) = A z (L/2 - z) + c on the lower half and -A (z - L/2)(L - z) + c on the upper half
(least squares for the amplitude A and a uniform offset c, both halves together) and prints eta = n g / (2 A)
with a standard error from the scatter of the bins about the fit.
"""
import argparse

import numpy as np

from .lammps_output import read_ave_chunk


def read_profile(path):
    """Last block of a fix ave/chunk file: columns chunk, coord, ncount, vx, density, temp."""
    return read_ave_chunk(path).data[-1]


def fit_viscosity(z, u, force, box, density):
    """Least squares for u = A shape(z) + c: the offset c absorbs the drift of the mean flow
    (the two halves' forces cancel only on average, and at low mass the mean velocity of the
    whole fluid wanders noticeably)."""
    half = box / 2
    shape = np.where(z < half, z * (half - z), -(z - half) * (box - z))
    design = np.column_stack([shape, np.ones_like(shape)])
    coefficients, _, _, _ = np.linalg.lstsq(design, u, rcond=None)
    residual = u - design @ coefficients
    dof = max(len(z) - 2, 1)
    covariance = np.linalg.inv(design.T @ design) * np.dot(residual, residual) / dof
    amplitude, amplitude_error = coefficients[0], np.sqrt(covariance[0, 0])
    eta = density * force / (2 * amplitude)
    return eta, eta * amplitude_error / abs(amplitude)


def parse_args(argv=None):
    parser = argparse.ArgumentParser()
    parser.add_argument("profile")
    parser.add_argument("--force", type=float, required=True)
    parser.add_argument("--box", type=float, default=10.0)
    parser.add_argument("--density", type=float, default=4.0)
    return parser.parse_args(argv)


def main(argv=None):
    args = parse_args(argv)
    data = read_profile(args.profile)
    eta, error = fit_viscosity(data[:, 1], data[:, 3], args.force, args.box, args.density)
    print(f"eta = {eta:.4f} +- {error:.4f}  (kBT in bins {np.mean(data[:, 5]):.4f})")


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Wavelength-dependent viscosity from transverse-current autocorrelations (TCAF).

Reads the output of LAMMPS ``fix ave/correlate`` applied to every value of
``compute dpd/tcurrent K`` (type auto), forms the normalised transverse-current
autocorrelation C_perp(k,t)/C_perp(k,0) averaged over the three box axes, both transverse
components and the real and imaginary parts, and fits for each k = 2 pi j / L

  Newtonian:  C(t)/C(0) = exp(-eta_k k^2 t / rho)
  Maxwell:    C(t)/C(0) = exp(-t/(2 tau_k)) [cosh(W t/(2 tau_k)) + sinh(W t/(2 tau_k))/W],
              W = sqrt(1 - 4 tau_k eta_k k^2 / rho)   (W imaginary: cos and sin instead)

then extrapolates eta_k = eta_0 + a k^2 from the smallest k and evaluates the Maxwell storage
modulus G'(w) = eta_k w^2 tau_k / (w^2 tau_k^2 + 1) and dynamic viscosity
eta'(w) = eta_k / (tau_k^2 w^2 + 1) (Phan-Thien, Mai-Duy and Nguyen, "A note on dissipative
particle dynamics (DPD) modelling of simple fluids").

Every output block of the fix (ave one) is fitted separately as well; the scatter of those
fits gives the standard errors.

  tcaf_fit.py tcaf.*.dat --box 15 --rho 4 --dt 0.001 --out tcaf_fit

writes tcaf_fit.dat (one row per k), tcaf_fit_summary.txt, tcaf_fit_moduli.dat and, unless
--no-plots, tcaf_fit_tcaf.png, tcaf_fit_eta.png and tcaf_fit_moduli.png.
"""
import argparse
import math
import sys

import numpy as np
from scipy.optimize import curve_fit

from . import statistics
from .lammps_output import read_ave_correlate


# ---- reading -------------------------------------------------------------------------------

def read_correlate(path):
    """Blocks of one fix ave/correlate file: list of (timestep, lags, counts, values)."""
    blocks = read_ave_correlate(path)    # rows: index, lag (steps), samples, values
    return [(step, rows[:, 1], rows[:, 2], rows[:, 3:]) for step, rows in zip(blocks.steps, blocks.data)]


def transverse_correlation(values, nwave):
    """Sum over axes, transverse components and Re/Im, divided by 6: <J*(0) J(t)> per k.

    values: (nlag, 12 K) autocorrelations in the layout of compute dpd/tcurrent
    (index = 4 (K axis + j - 1) + 2 t + part). Returns (K, nlag)."""
    nlag = values.shape[0]
    per_wave = values.reshape(nlag, 3, nwave, 4)
    return per_wave.sum(axis=(1, 3)).T / 6.0


def load(paths, min_count=1):
    """Blocks from all files -> (lag steps, array (nblock, K, nlag)); incomplete blocks
    (a lag without samples) are dropped."""
    corr, lags = [], None
    for path in paths:
        for step, lag, count, values in read_correlate(path):
            if values.shape[1] % 12:
                raise ValueError(f"{path}: {values.shape[1]} values per lag is not 12 K; "
                                 "was every value of compute dpd/tcurrent correlated (type auto)?")
            if count.min() < min_count:
                print(f"{path}: skipping block at step {step} (a lag has {int(count.min())} "
                      "samples)", file=sys.stderr)
                continue
            if lags is None:
                lags = lag
            elif len(lag) != len(lags) or np.any(lag != lags):
                raise ValueError(f"{path}: blocks with different lags cannot be combined")
            corr.append(transverse_correlation(values, values.shape[1] // 12))
    if not corr:
        raise ValueError("no complete correlation blocks in " + ", ".join(paths))
    return lags, np.array(corr)


# ---- models --------------------------------------------------------------------------------

def newtonian(t, rate):
    return np.exp(-rate * t)


def maxwell(t, eta, tau, k2_over_rho):
    """Maxwell TCAF for both branches of W^2 = 1 - 4 tau eta k^2 / rho."""
    w2 = 1.0 - 4.0 * tau * eta * k2_over_rho
    u = np.asarray(t) / (2.0 * tau)
    if w2 > 1e-6:
        w = math.sqrt(w2)
        # cosh + sinh/W without overflow: two decaying exponentials
        return 0.5 * ((1.0 + 1.0 / w) * np.exp(-(1.0 - w) * u) +
                      (1.0 - 1.0 / w) * np.exp(-(1.0 + w) * u))
    if w2 < -1e-6:
        w = math.sqrt(-w2)
        return np.exp(-u) * (np.cos(w * u) + np.sin(w * u) / w)
    return np.exp(-u) * (1.0 + u)    # critical damping, the limit of both branches


def storage_modulus(omega, eta, tau):
    return eta * omega ** 2 * tau / (omega ** 2 * tau ** 2 + 1.0)


def dynamic_viscosity(omega, eta, tau):
    return eta / (tau ** 2 * omega ** 2 + 1.0)


# ---- fits ----------------------------------------------------------------------------------

def fit_window(c_norm, threshold, min_points=5):
    """Number of leading points to fit: up to the first value below threshold."""
    below = np.nonzero(c_norm < threshold)[0]
    n = below[0] if below.size else len(c_norm)
    return max(n, min(min_points, len(c_norm)))


def fit_newtonian(t, c_norm, k2_over_rho):
    """eta_k from exp(-eta k^2 t / rho)."""
    # start from the slope of log C over the window
    positive = c_norm > 0
    guess = -np.polyfit(t[positive], np.log(c_norm[positive]), 1)[0] if positive.sum() > 1 else 1.0
    guess = guess if guess > 0 else 1.0 / max(t[-1], 1e-12)
    (rate,), _ = curve_fit(newtonian, t, c_norm, p0=[guess], bounds=(0.0, np.inf))
    return rate / k2_over_rho


def fit_maxwell(t, c_norm, k2_over_rho, eta_guess):
    """(eta_k, tau_k) of the Maxwell model; tries starts on both branches of W, keeps the best."""
    rate = eta_guess * k2_over_rho
    best = None
    for tau0 in np.array([1e-3, 1e-2, 0.1, 0.5, 2.0, 10.0]) / rate:
        def model(tt, eta, tau):
            return maxwell(tt, eta, tau, k2_over_rho)
        try:
            p, _ = curve_fit(model, t, c_norm, p0=[eta_guess, tau0],
                             bounds=([0.0, 1e-12], [np.inf, np.inf]), max_nfev=2000)
        except (RuntimeError, ValueError):
            continue
        sse = float(np.sum((model(t, *p) - c_norm) ** 2))
        if best is None or sse < best[0]:
            best = (sse, p)
    if best is None:
        return float("nan"), float("nan")
    return float(best[1][0]), float(best[1][1])


def standard_error(samples):
    """Standard error of the finite samples (a block whose fit failed gives nan)."""
    samples = np.asarray(samples, dtype=float)
    return float(statistics.standard_error(samples[np.isfinite(samples)]))


def extrapolate(k, eta, err, nfit):
    """eta_k = eta_0 + a k^2 on the nfit smallest k: (eta0, a, err_eta0, err_a). Weighted by the
    errors of eta_k where they all exist; else unweighted, without errors."""
    order = np.argsort(k)[:nfit]
    x, y, s = k[order] ** 2, eta[order], err[order]
    if np.all(np.isfinite(s)) and np.all(s > 0):
        (a, eta0), cov = np.polyfit(x, y, 1, w=1.0 / s, cov="unscaled")
        return eta0, a, math.sqrt(cov[1, 1]), math.sqrt(cov[0, 0])
    a, eta0 = np.polyfit(x, y, 1)
    return eta0, a, float("nan"), float("nan")


def analyse(lags, corr, box, rho, dt, threshold=0.05, natoms=None):
    """Fits of every k; returns a list of dicts (one per k) and the fitted mean curves."""
    nblock, nwave, _ = corr.shape
    t = lags * dt
    mean = corr.mean(axis=0)
    results = []
    for j in range(1, nwave + 1):
        k = 2.0 * math.pi * j / box
        k2r = k * k / rho
        c_mean = mean[j - 1] / mean[j - 1][0]
        n = fit_window(c_mean, threshold)
        eta_n = fit_newtonian(t[:n], c_mean[:n], k2r)
        eta_m, tau_m = fit_maxwell(t[:n], c_mean[:n], k2r, eta_n)
        per_block = []
        for b in range(nblock):
            cb = corr[b, j - 1] / corr[b, j - 1][0]
            en = fit_newtonian(t[:n], cb[:n], k2r)
            em, tm = fit_maxwell(t[:n], cb[:n], k2r, eta_n) if nblock > 1 else (en, 0.0)
            per_block.append((en, em, tm))
        per_block = np.array(per_block)
        row = {
            "j": j, "k": k, "C0": mean[j - 1][0], "n_fit": n, "t_fit": t[n - 1],
            "eta_newton": eta_n, "err_newton": standard_error(per_block[:, 0]),
            "eta_maxwell": eta_m, "err_maxwell": standard_error(per_block[:, 1]),
            "tau_maxwell": tau_m, "err_tau": standard_error(per_block[:, 2]),
            "omega2": 1.0 - 4.0 * tau_m * eta_m * k2r,
        }
        if natoms:
            # equipartition: <|J_perp|^2> = N kBT / m
            row["kT_over_m"] = mean[j - 1][0] / natoms
        results.append(row)
    return t, mean, results


# ---- output --------------------------------------------------------------------------------

def write_table(path, results, nblock):
    """One row per k: the fits and their errors."""
    columns = ["j", "k", "eta_newton", "err_newton", "eta_maxwell", "err_maxwell",
               "tau_maxwell", "err_tau", "omega2", "n_fit", "t_fit", "C0"]
    if "kT_over_m" in results[0]:
        columns.append("kT_over_m")
    with open(path, "w") as out:
        out.write("# TCAF fits per wave number k = 2 pi j / L; errors are standard errors over "
                  f"{nblock} blocks\n# omega2 = 1 - 4 tau eta k^2/rho (< 0: oscillating branch)\n")
        out.write("# " + " ".join(columns) + "\n")
        for r in results:
            out.write(" ".join(f"{r[c]:.8g}" for c in columns) + "\n")


def extrapolations(args, t, results, nblock):
    """eta_0 of both models ({model: extrapolate(...)}) and the summary's lines."""
    k = np.array([r["k"] for r in results])
    summary = [f"blocks: {nblock}, lags: {len(t)} (0 ... {t[-1]:g}), box {args.box}, rho {args.rho}",
               f"extrapolation eta_k = eta_0 + a k^2 on the {args.nfit} smallest k "
               f"({', '.join(f'{x:.4f}' for x in np.sort(k)[:args.nfit])}):"]
    fits = {}
    for model in ("newton", "maxwell"):
        eta = np.array([r["eta_" + model] for r in results])
        err = np.array([r["err_" + model] for r in results])
        fits[model] = extrapolate(k, eta, err, args.nfit)
        e0, a, se0, sa = fits[model]
        name = "Newtonian" if model == "newton" else "Maxwell"
        summary.append(f"  {name:9s}: eta_0 = {e0:.4f} +- {se0:.4f}, a = {a:.4f} +- {sa:.4f}")
    for label, value in args.reference:
        summary.append(f"  reference {label}: {value:g}")
    return fits, summary


def write_moduli(path, smallest):
    """G'(w) and eta'(w) of the Maxwell fits of the given k, over four decades about 1/tau;
    returns the frequencies."""
    taus = [r["tau_maxwell"] for r in smallest if r["tau_maxwell"] > 0]
    lo = 1e-2 / max(taus) if taus else 1e-2
    hi = 1e2 / min(taus) if taus else 1e2
    omega = np.logspace(math.log10(lo), math.log10(hi), 200)
    with open(path, "w") as out:
        out.write("# omega " + " ".join(f"G'(k={r['k']:.4f}) eta'(k={r['k']:.4f})" for r in smallest)
                  + "\n")
        for w in omega:
            vals = []
            for r in smallest:
                vals += [storage_modulus(w, r["eta_maxwell"], r["tau_maxwell"]),
                         dynamic_viscosity(w, r["eta_maxwell"], r["tau_maxwell"])]
            out.write(f"{w:.6g} " + " ".join(f"{v:.6g}" for v in vals) + "\n")
    return omega


def write_outputs(args, t, mean, results, nblock):
    write_table(args.out + ".dat", results, nblock)
    fits, summary = extrapolations(args, t, results, nblock)
    with open(args.out + "_summary.txt", "w") as out:
        out.write("\n".join(summary) + "\n")
    print("\n".join(summary))
    smallest = sorted(results, key=lambda r: r["k"])[:args.nfit]
    omega = write_moduli(args.out + "_moduli.dat", smallest)
    if not args.no_plots:
        plot(args, t, mean, results, smallest, omega, fits)
    return fits


def plot(args, t, mean, results, smallest, omega, fits):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    k2r = {r["j"]: r["k"] ** 2 / args.rho for r in results}
    fig, ax = plt.subplots(figsize=(5.5, 4))
    for r in smallest:
        c = mean[r["j"] - 1] / mean[r["j"] - 1][0]
        line, = ax.plot(t, c, ".", ms=2, label=f"k = {r['k']:.3f}")
        ax.plot(t, newtonian(t, r["eta_newton"] * k2r[r["j"]]), "-", color=line.get_color(), lw=1)
        ax.plot(t, maxwell(t, r["eta_maxwell"], r["tau_maxwell"], k2r[r["j"]]), "--",
                color=line.get_color(), lw=1)
    ax.axhline(0.0, color="grey", lw=0.5)
    ax.set_xlabel("t")
    ax.set_ylabel(r"$C_\perp(k,t)/C_\perp(k,0)$")
    ax.set_title("TCAF: data, Newtonian (solid) and Maxwell (dashed) fits", fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.out + "_tcaf.png", dpi=100)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(5.5, 4))
    k = np.array([r["k"] for r in results])
    for model, marker, name in (("newton", "o", "Newtonian"), ("maxwell", "s", "Maxwell")):
        eta = np.array([r["eta_" + model] for r in results])
        err = np.array([r["err_" + model] for r in results])
        ax.errorbar(k, eta, yerr=np.nan_to_num(err), fmt=marker, ms=3, capsize=2, mfc="none",
                    label=f"{name} fit")
        e0, a = fits[model][:2]
        kk = np.linspace(0.0, np.sort(k)[min(args.nfit, len(k)) - 1] * 1.3, 50)
        ax.plot(kk, e0 + a * kk ** 2, "-", lw=0.8)
    for label, value in args.reference:
        ax.axhline(value, ls=":", lw=1, color="k")
        ax.annotate(f"{label} {value:g}", (k.max(), value), ha="right", va="bottom", fontsize=7)
    ax.set_xlabel("k")
    ax.set_ylabel(r"$\eta_k$")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.out + "_eta.png", dpi=100)
    plt.close(fig)

    fig, (a1, a2) = plt.subplots(1, 2, figsize=(8, 3.5))
    for r in smallest:
        a1.loglog(omega, storage_modulus(omega, r["eta_maxwell"], r["tau_maxwell"]),
                  label=f"k = {r['k']:.3f}")
        a2.semilogx(omega, dynamic_viscosity(omega, r["eta_maxwell"], r["tau_maxwell"]))
    a1.set_xlabel(r"$\omega$")
    a1.set_ylabel(r"$G'(\omega)$")
    a2.set_xlabel(r"$\omega$")
    a2.set_ylabel(r"$\eta'(\omega)$")
    a1.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(args.out + "_moduli.png", dpi=100)
    plt.close(fig)


def parse_reference(text):
    if "=" not in text:
        raise argparse.ArgumentTypeError(f"expected LABEL=VALUE, got {text!r}")
    label, value = text.rsplit("=", 1)
    return label, float(value)


def parse_args(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("files", nargs="+", help="fix ave/correlate output files")
    parser.add_argument("--box", type=float, required=True, help="cubic box side L")
    parser.add_argument("--rho", type=float, required=True, help="mass density m n")
    parser.add_argument("--dt", type=float, default=0.001, help="time step (default 0.001)")
    parser.add_argument("--nfit", type=int, default=4,
                        help="smallest k used for eta_k = eta_0 + a k^2 (default 4)")
    parser.add_argument("--threshold", type=float, default=0.05,
                        help="fit each TCAF up to where it first falls below this (default 0.05)")
    parser.add_argument("--natoms", type=int, help="atoms in the group (reports kBT/m from C(k,0))")
    parser.add_argument("--reference", type=parse_reference, action="append", default=[],
                        metavar="LABEL=VALUE", help="reference viscosity drawn in the eta plot")
    parser.add_argument("--out", default="tcaf_fit", help="prefix of the output files")
    parser.add_argument("--no-plots", action="store_true")
    args = parser.parse_args(argv)
    if args.box <= 0 or args.rho <= 0 or args.dt <= 0 or args.nfit < 2:
        parser.error("--box, --rho and --dt must be > 0 and --nfit >= 2")
    args.error = parser.error
    return args


def run(args):
    """Read, fit and write everything; returns the extrapolations {model: (eta_0, a, errors)}."""
    lags, corr = load(args.files)
    if args.nfit > corr.shape[1]:
        args.error(f"--nfit {args.nfit} exceeds the {corr.shape[1]} wave numbers in the data")
    t, mean, results = analyse(lags, corr, args.box, args.rho, args.dt, args.threshold,
                               args.natoms)
    return write_outputs(args, t, mean, results, corr.shape[0])


def main(argv=None):
    run(parse_args(argv))
    return 0


if __name__ == "__main__":
    main()

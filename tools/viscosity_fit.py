#!/usr/bin/python3
"""Viscosity from a reverse-Poiseuille profile written by validation/in.reverse_poiseuille.

Usage: tools/viscosity_fit.py PROFILE --force G [--box L] [--density N]
Fits u(z) = A z (L/2 - z) on the lower half and -A (z - L/2)(L - z) on the upper half
(least squares for the one amplitude A, both halves together) and prints eta = n g / (2 A)
with a standard error from the scatter of the bins about the fit.
"""
import argparse

import numpy as np


def read_profile(path):
    """Last block of a fix ave/chunk file: columns chunk, coord, ncount, vx, density, temp."""
    blocks, current = [], []
    for line in open(path):
        if line.startswith("#"):
            continue
        fields = line.split()
        if len(fields) == 3:
            if current:
                blocks.append(current)
            current = []
        else:
            current.append([float(x) for x in fields])
    if current:
        blocks.append(current)
    return np.array(blocks[-1])


def fit_viscosity(z, u, force, box, density):
    half = box / 2
    shape = np.where(z < half, z * (half - z), -(z - half) * (box - z))
    amplitude = np.dot(shape, u) / np.dot(shape, shape)
    residual = u - amplitude * shape
    dof = max(len(z) - 1, 1)
    amplitude_error = np.sqrt(np.dot(residual, residual) / dof / np.dot(shape, shape))
    eta = density * force / (2 * amplitude)
    return eta, eta * amplitude_error / abs(amplitude)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("profile")
    parser.add_argument("--force", type=float, required=True)
    parser.add_argument("--box", type=float, default=10.0)
    parser.add_argument("--density", type=float, default=4.0)
    args = parser.parse_args()
    data = read_profile(args.profile)
    eta, error = fit_viscosity(data[:, 1], data[:, 3], args.force, args.box, args.density)
    print(f"eta = {eta:.4f} +- {error:.4f}  (kBT in bins {np.mean(data[:, 5]):.4f})")


if __name__ == "__main__":
    main()

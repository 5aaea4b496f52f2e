"""ETD-DPD post-processing: readers for LAMMPS's output files (lammps_output), the kinetic theory
of the DPD fluid (kinetic_theory, the twin of src/kernels/kinetic_theory.h), shared statistics
(statistics) and the analyses of the package's examples and validation studies. Each analysis
module has a main(); the scripts in python/ call it (python3 python/<module>.py --help)."""

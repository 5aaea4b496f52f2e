"""ETD-DPD post-processing: readers for LAMMPS's output files and the analyses of the package's
examples and validation studies. Each analysis module has a main(); the scripts in python/ call
it (python3 python/<module>.py --help)."""

# The Debian packages that ETD-DPD builds, tests and documents with: installed by
# tools/bootstrap.sh on the host and by tools/kokkos/sid_chroot.sh in its sid root. Sourced.
debian_packages=(build-essential cmake libopenmpi-dev openmpi-bin libgtest-dev librandom123-dev libboost-dev
                 python3 python3-numpy python3-scipy python3-matplotlib python3-sphinx
                 python3-sphinx-rtd-theme dpkg-dev xz-utils curl gpgv debian-archive-keyring)

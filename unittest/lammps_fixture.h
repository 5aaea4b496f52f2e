// ETD-DPD test support: an in-process LAMMPS instance with the plugin loaded.
#ifndef ETD_LAMMPS_FIXTURE_H
#define ETD_LAMMPS_FIXTURE_H

#include <mpi.h>

#include <functional>
#include <string>
#include <vector>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace etdtest {

class Lammps {
 public:
  // comm: the ranks this instance runs on (MPI_COMM_WORLD by default); args: further
  // command-line arguments (for example -k on t 2 -sf kk)
  explicit Lammps(MPI_Comm comm = MPI_COMM_WORLD, bool load_plugin = true,
                  const std::vector<std::string> &args = {});
  ~Lammps();
  Lammps(const Lammps &) = delete;
  Lammps &operator=(const Lammps &) = delete;

  void cmd(const std::string &line);    // throws std::runtime_error on ERROR
  void cmds(const std::vector<std::string> &lines);
  // Runs the command and returns the LAMMPS error message ("" if it succeeded).
  std::string error_of(const std::string &line);
  std::string error_of(const std::vector<std::string> &lines);

  // per-atom property ordered by atom ID, on every rank of the instance
  std::vector<double> gather(const std::string &name, int count = 3);
  std::vector<double> gather_compute(const std::string &id, int columns);    // per-atom compute
  double thermo(const std::string &keyword);
  double compute_scalar(const std::string &id);
  double compute_vector(const std::string &id, int index);    // 0-based
  double fix_vector(const std::string &id, int index);
  double fix_scalar(const std::string &id);
  long natoms();

  LAMMPS_NS::LAMMPS *lmp = nullptr;
  MPI_Comm comm;
};

// A bad-input case: commands run after the test's set-up, and a piece of the ERROR message they
// must stop with ("" where LAMMPS's own check stops them: only that it stops is ours to test).
struct BadInput {
  std::vector<std::string> commands;
  std::string expected;
};
// Runs every case in a fresh instance prepared by setup and checks that it stops with an ERROR
// that contains the expected text; args: the instances' further command-line arguments.
void expect_errors(const std::vector<BadInput> &cases, const std::function<void(Lammps &)> &setup,
                   const std::vector<std::string> &args = {});

// A data file with n atoms at random positions in a cube of side L (deterministic).
void write_random_data(const std::string &path, int natoms, double L, unsigned seed, int ntypes = 1,
                       double vmax = 0.0);
// The same for atom_style sphere: diameter d, mass 1 (density 6/(pi d^3)), random velocities
// in [-vmax, vmax] and angular velocities in [-wmax, wmax].
void write_random_sphere_data(const std::string &path, int natoms, double L, unsigned seed,
                              int ntypes = 1, double vmax = 0.0, double wmax = 0.0,
                              double diameter = 1.0);
std::string work_file(const std::string &name);    // a path in the test's build folder
std::string read_file(const std::string &path);    // its text ("" where it cannot be read)
int world_rank();
int world_size();
// Runs body with a LAMMPS instance on the first `ranks` world ranks (the others wait); returns
// what body returned there (what it gathered, on world rank 0). For rank-count comparisons in
// one MPI program.
std::vector<double> on_ranks(int ranks, const std::function<std::vector<double>(Lammps &)> &body);

}    // namespace etdtest

#endif

#include "lammps_fixture.h"

#include <gtest/gtest.h>

#include "atom.h"
#include "exceptions.h"
#include "input.h"
#include "lammps.h"
#include "library.h"
#include "modify.h"

#include <cstdio>
#include <random>
#include <stdexcept>
#include <vector>

namespace etdtest {

Lammps::Lammps(MPI_Comm comm_, bool load_plugin, const std::vector<std::string> &args) : comm(comm_)
{
  std::vector<std::string> words = {"etd_test", "-log", "none", "-screen", "none", "-nocite"};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char *> argv;
  for (std::string &word : words) argv.push_back(word.data());
  lmp = new LAMMPS_NS::LAMMPS(static_cast<int>(argv.size()), argv.data(), comm);
  if (load_plugin) cmd(std::string("plugin load ") + ETD_PLUGIN_PATH);
}

Lammps::~Lammps()
{
  delete lmp;
}

void Lammps::cmd(const std::string &line)
{
  try {
    lmp->input->one(line);
  } catch (LAMMPS_NS::LAMMPSException &e) {
    throw std::runtime_error("LAMMPS ERROR in '" + line + "': " + e.what());
  }
}

void Lammps::cmds(const std::vector<std::string> &lines)
{
  for (const auto &line : lines) cmd(line);
}

std::string Lammps::error_of(const std::string &line)
{
  try {
    lmp->input->one(line);
  } catch (LAMMPS_NS::LAMMPSException &e) {
    const std::string message = e.what();
    return message.empty() ? std::string("(empty error)") : message;
  }
  return "";
}

std::string Lammps::error_of(const std::vector<std::string> &lines)
{
  for (const auto &line : lines) {
    std::string message = error_of(line);
    if (!message.empty()) return message;
  }
  return "";
}

std::vector<double> Lammps::gather(const std::string &name, int count)
{
  std::vector<double> data(static_cast<size_t>(natoms()) * count);
  std::vector<char> buffer(name.begin(), name.end());
  buffer.push_back('\0');
  lammps_gather_atoms(lmp, buffer.data(), 1, count, data.data());
  return data;
}

std::vector<double> Lammps::gather_compute(const std::string &id, int columns)
{
  // compute values ordered by atom ID, assembled with an allreduce over the instance
  auto *c = static_cast<double **>(lammps_extract_compute(lmp, id.c_str(), 1, 2));
  const long n = natoms();
  std::vector<double> local(static_cast<size_t>(n) * columns, 0.0), global(local.size(), 0.0);
  auto *tag = lmp->atom->tag;
  for (int i = 0; i < lmp->atom->nlocal; i++)
    for (int k = 0; k < columns; k++) local[(tag[i] - 1) * columns + k] = c[i][k];
  MPI_Allreduce(local.data(), global.data(), static_cast<int>(local.size()), MPI_DOUBLE, MPI_SUM,
                comm);
  return global;
}

double Lammps::thermo(const std::string &keyword)
{
  return lammps_get_thermo(lmp, keyword.c_str());
}

double Lammps::compute_scalar(const std::string &id)
{
  return *static_cast<double *>(lammps_extract_compute(lmp, id.c_str(), 0, 0));
}

double Lammps::compute_vector(const std::string &id, int index)
{
  return static_cast<double *>(lammps_extract_compute(lmp, id.c_str(), 0, 1))[index];
}

double Lammps::fix_vector(const std::string &id, int index)
{
  auto *value = static_cast<double *>(lammps_extract_fix(lmp, id.c_str(), 0, 1, index, 0));
  double result = *value;
  lammps_free(value);
  return result;
}

double Lammps::fix_scalar(const std::string &id)
{
  auto *value = static_cast<double *>(lammps_extract_fix(lmp, id.c_str(), 0, 0, 0, 0));
  double result = *value;
  lammps_free(value);
  return result;
}

long Lammps::natoms()
{
  return static_cast<long>(lammps_get_natoms(lmp));
}

void write_random_data(const std::string &path, int natoms, double L, unsigned seed, int ntypes,
                       double vmax)
{
  if (world_rank() == 0) {
    std::mt19937_64 gen(seed);
    std::uniform_real_distribution<double> pos(0.0, L), vel(-vmax, vmax);
    std::FILE *fp = std::fopen(path.c_str(), "w");
    if (!fp) throw std::runtime_error("cannot write " + path);
    std::fprintf(fp, "ETD-DPD test configuration\n\n%d atoms\n%d atom types\n\n", natoms, ntypes);
    std::fprintf(fp, "0 %.17g xlo xhi\n0 %.17g ylo yhi\n0 %.17g zlo zhi\n\nMasses\n\n", L, L, L);
    for (int t = 1; t <= ntypes; t++) std::fprintf(fp, "%d 1.0\n", t);
    std::fprintf(fp, "\nAtoms # atomic\n\n");
    for (int i = 1; i <= natoms; i++) {
      const double x = pos(gen), y = pos(gen), z = pos(gen);
      std::fprintf(fp, "%d %d %.17g %.17g %.17g\n", i, 1 + (i - 1) % ntypes, x, y, z);
    }
    std::fprintf(fp, "\nVelocities\n\n");
    for (int i = 1; i <= natoms; i++) {
      const double vx = vel(gen), vy = vel(gen), vz = vel(gen);
      std::fprintf(fp, "%d %.17g %.17g %.17g\n", i, vx, vy, vz);
    }
    std::fclose(fp);
  }
  MPI_Barrier(MPI_COMM_WORLD);
}

void write_random_sphere_data(const std::string &path, int natoms, double L, unsigned seed,
                              int ntypes, double vmax, double wmax, double diameter)
{
  if (world_rank() == 0) {
    std::mt19937_64 gen(seed);
    std::uniform_real_distribution<double> pos(0.0, L), vel(-vmax, vmax), spin(-wmax, wmax);
    const double density = 6.0 / (3.14159265358979323846 * diameter * diameter * diameter);
    std::FILE *fp = std::fopen(path.c_str(), "w");
    if (!fp) throw std::runtime_error("cannot write " + path);
    std::fprintf(fp, "ETD-DPD test configuration (spheres)\n\n%d atoms\n%d atom types\n\n", natoms,
                 ntypes);
    std::fprintf(fp, "0 %.17g xlo xhi\n0 %.17g ylo yhi\n0 %.17g zlo zhi\n\nAtoms # sphere\n\n", L,
                 L, L);
    for (int i = 1; i <= natoms; i++) {
      const double x = pos(gen), y = pos(gen), z = pos(gen);
      std::fprintf(fp, "%d %d %.17g %.17g %.17g %.17g %.17g\n", i, 1 + (i - 1) % ntypes, diameter,
                   density, x, y, z);
    }
    std::fprintf(fp, "\nVelocities\n\n");
    for (int i = 1; i <= natoms; i++) {
      const double vx = vel(gen), vy = vel(gen), vz = vel(gen);
      const double wx = spin(gen), wy = spin(gen), wz = spin(gen);
      std::fprintf(fp, "%d %.17g %.17g %.17g %.17g %.17g %.17g\n", i, vx, vy, vz, wx, wy, wz);
    }
    std::fclose(fp);
  }
  MPI_Barrier(MPI_COMM_WORLD);
}

std::string work_file(const std::string &name)
{
  return std::string(ETD_TEST_WORKDIR) + "/" + name;
}

std::string read_file(const std::string &path)
{
  std::string text;
  if (FILE *f = std::fopen(path.c_str(), "r")) {
    char buffer[4096];
    size_t n;
    while ((n = std::fread(buffer, 1, sizeof buffer, f)) > 0) text.append(buffer, n);
    std::fclose(f);
  }
  return text;
}

int world_rank()
{
  int r;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

int world_size()
{
  int s;
  MPI_Comm_size(MPI_COMM_WORLD, &s);
  return s;
}

std::vector<double> on_ranks(int ranks, const std::function<std::vector<double>(Lammps &)> &body)
{
  MPI_Comm comm;
  const int rank = world_rank();
  MPI_Comm_split(MPI_COMM_WORLD, rank < ranks ? 0 : MPI_UNDEFINED, rank, &comm);
  std::vector<double> result;
  if (comm != MPI_COMM_NULL) {
    Lammps l(comm);
    result = body(l);
    MPI_Comm_free(&comm);
  }
  MPI_Barrier(MPI_COMM_WORLD);
  return result;
}

void expect_errors(const std::vector<BadInput> &cases, const std::function<void(Lammps &)> &setup,
                   const std::vector<std::string> &args)
{
  for (const BadInput &c : cases) {
    Lammps l(MPI_COMM_WORLD, true, args);
    setup(l);
    const std::string message = l.error_of(c.commands);
    EXPECT_FALSE(message.empty()) << "commands ending '" << c.commands.back() << "' gave no ERROR";
    EXPECT_NE(message.find(c.expected), std::string::npos)
        << "commands ending '" << c.commands.back() << "' gave: '" << message << "'";
  }
}

}    // namespace etdtest

// ETD-DPD: the coefficients of the package's pair styles, from their description
// (pair_coeff_description.h): pair_coeff, init_one's part, restart per type pair, write_data,
// extract.
#include "pair_dpd_base.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "utils.h"

#include <algorithm>
#include <cstring>

using namespace LAMMPS_NS;
using etd::CoeffArg;
using etd::CoeffBound;
using etd::CoeffParam;

/* ----------------------------------------------------------------------
   pair_coeff I J required... [optional...] [keyword value ...]
------------------------------------------------------------------------- */

std::string PairDPDBase::coeff_usage() const
{
  std::string usage = "I J";
  for (int p = 0; p < description.count; p++) {
    const CoeffParam &param = description.params[p];
    if (param.arg == CoeffArg::Required) usage += std::string(" ") + param.name;
  }
  for (int p = 0; p < description.count; p++) {
    const CoeffParam &param = description.params[p];
    if (param.arg == CoeffArg::Optional) usage += std::string(" [") + param.name + "]";
  }
  for (int p = 0; p < description.count; p++) {
    const CoeffParam &param = description.params[p];
    if (param.arg == CoeffArg::Keyword)
      usage += std::string(" [") + param.name + " " + param.value_name + "]";
  }
  return usage;
}

double PairDPDBase::parse_coeff(const CoeffParam &param, const char *arg)
{
  const double value = utils::numeric(FLERR, arg, false, lmp);
  if (param.bound == CoeffBound::NonNegative && value < 0.0)
    error->all(FLERR, "pair_coeff {}: {} must be >= 0, got {}", style_name, param.what, arg);
  if (param.bound == CoeffBound::Positive && value <= 0.0)
    error->all(FLERR, "pair_coeff {}: {} must be > 0, got {}", style_name, param.what, arg);
  return value;
}

void PairDPDBase::coeff(int narg, char **arg)
{
  const int count = description.count;
  int required = 0, optional = 0, keywords = 0;
  for (int p = 0; p < count; p++) {
    const CoeffArg kind = description.params[p].arg;
    required += kind == CoeffArg::Required;
    optional += kind == CoeffArg::Optional;
    keywords += kind == CoeffArg::Keyword;
  }
  // with keywords, an extra argument is reported by its text below
  if (narg < 2 + required || (keywords == 0 && narg > 2 + required + optional))
    error->all(FLERR, "Incorrect args for pair_coeff {}: expected {}, got {} arguments", style_name,
               coeff_usage(), narg);
  if (!allocated) allocate();

  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);

  auto keyword_index = [&](const char *word) {
    for (int p = 0; p < count; p++)
      if (description.params[p].arg == CoeffArg::Keyword &&
          std::strcmp(word, description.params[p].name) == 0)
        return p;
    return -1;
  };
  std::vector<double> value(count);
  std::vector<int> given(count, 0);
  int iarg = 2;
  for (int p = 0; p < count; p++)
    if (description.params[p].arg == CoeffArg::Required) {
      value[p] = parse_coeff(description.params[p], arg[iarg++]);
      given[p] = 1;
    }
  for (int p = 0; p < count; p++)
    if (description.params[p].arg == CoeffArg::Optional && iarg < narg &&
        keyword_index(arg[iarg]) < 0) {
      value[p] = parse_coeff(description.params[p], arg[iarg++]);
      given[p] = 1;
    }
  while (iarg < narg) {
    const int p = keyword_index(arg[iarg]);
    if (p < 0)
      error->all(FLERR, "pair_coeff {}: unknown keyword or extra argument '{}'", style_name,
                 arg[iarg]);
    if (iarg + 2 > narg)
      error->all(FLERR, "pair_coeff {}: keyword {} needs a value", style_name, arg[iarg]);
    value[p] = parse_coeff(description.params[p], arg[iarg + 1]);
    given[p] = 1;
    iarg += 2;
  }
  // defaults: values first, then those taken from another parameter
  for (int p = 0; p < count; p++) {
    const CoeffParam &param = description.params[p];
    if (!given[p] && param.default_from == etd::DEFAULT_VALUE) value[p] = param.default_value;
    if (!given[p] && param.default_from == etd::DEFAULT_CUTOFF) value[p] = cut_global;
  }
  for (int p = 0; p < count; p++)
    if (!given[p] && description.params[p].default_from >= 0)
      value[p] = value[description.params[p].default_from];

  int pairs = 0;
  for (int i = ilo; i <= ihi; i++) {
    for (int j = std::max(jlo, i); j <= jhi; j++) {
      for (int p = 0; p < count; p++) {
        coeff_values[p][i][j] = value[p];
        if (coeff_given[p]) coeff_given[p][i][j] = given[p];
      }
      setflag[i][j] = 1;
      pairs++;
    }
  }
  if (pairs == 0)
    error->all(FLERR, "pair_coeff {}: no type pairs selected by {} {}", style_name, arg[0], arg[1]);
}

/* ---------------------------------------------------------------------- */

double PairDPDBase::init_type_pair(int i, int j)
{
  if (setflag[i][j] == 0)
    error->all(FLERR, "Pair style {}: pair coefficients for types {} {} are not set (no mixing)",
               style_name, i, j);
  double range = 0.0;
  for (int p = 0; p < description.count; p++) {
    const CoeffParam &param = description.params[p];
    if (coeff_given[p] && !coeff_given[p][i][j])
      coeff_values[p][i][j] = coeff_values[param.default_from][i][j];
  }
  for (int p = 0; p < description.count; p++) {
    coeff_values[p][j][i] = coeff_values[p][i][j];
    if (coeff_given[p]) coeff_given[p][j][i] = coeff_given[p][i][j];
    if (description.params[p].range) range = std::max(range, coeff_values[p][i][j]);
  }
  return range;
}

void PairDPDBase::type_pair_values(int i, int j, double *values) const
{
  for (int p = 0; p < description.count; p++) values[p] = coeff_values[p][i][j];
}

/* ----------------------------------------------------------------------
   restart file: per set type pair its values in the description's order, then for each
   parameter that defaults to another whether it was given
------------------------------------------------------------------------- */

void PairDPDBase::write_type_pair(FILE *fp, int i, int j)
{
  std::vector<double> values(description.count);
  type_pair_values(i, j, values.data());
  fwrite(values.data(), sizeof(double), description.count, fp);
  for (int p = 0; p < description.count; p++)
    if (coeff_given[p]) fwrite(&coeff_given[p][i][j], sizeof(int), 1, fp);
}

void PairDPDBase::read_type_pair(FILE *fp, int i, int j)
{
  std::vector<double> values(description.count);
  std::vector<int> given;
  for (int p = 0; p < description.count; p++)
    if (coeff_given[p]) given.push_back(0);
  if (comm->me == 0) {
    utils::sfread(FLERR, values.data(), sizeof(double), values.size(), fp, nullptr, error);
    if (!given.empty())
      utils::sfread(FLERR, given.data(), sizeof(int), given.size(), fp, nullptr, error);
  }
  MPI_Bcast(values.data(), values.size(), MPI_DOUBLE, 0, world);
  if (!given.empty()) MPI_Bcast(given.data(), given.size(), MPI_INT, 0, world);
  int flag = 0;
  for (int p = 0; p < description.count; p++) {
    coeff_values[p][i][j] = values[p];
    if (coeff_given[p]) coeff_given[p][i][j] = given[flag++];
  }
}

/* ----------------------------------------------------------------------
   data file: the positional values, then each keyword with its value
------------------------------------------------------------------------- */

void PairDPDBase::write_type_pair_data(FILE *fp, int i, int j)
{
  for (int p = 0; p < description.count; p++)
    if (description.params[p].arg != CoeffArg::Keyword)
      fprintf(fp, " %.15g", coeff_values[p][i][j]);
  for (int p = 0; p < description.count; p++)
    if (description.params[p].arg == CoeffArg::Keyword)
      fprintf(fp, " %s %.15g", description.params[p].name, coeff_values[p][i][j]);
  fprintf(fp, "\n");
}

void PairDPDBase::write_data(FILE *fp)
{
  for (int i = 1; i <= atom->ntypes; i++) {
    fprintf(fp, "%d", i);
    write_type_pair_data(fp, i, i);
  }
}

void PairDPDBase::write_data_all(FILE *fp)
{
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      fprintf(fp, "%d %d", i, j);
      write_type_pair_data(fp, i, j);
    }
}

void *PairDPDBase::extract(const char *name, int &dim)
{
  dim = 2;
  if (!allocated) return nullptr;
  for (int p = 0; p < description.count; p++) {
    const char *extract_name = description.params[p].extract_name;
    if (extract_name && std::strcmp(name, extract_name) == 0) return (void *) coeff_values[p];
  }
  return nullptr;
}

// ETD-DPD: a pair style's per type pair coefficients, each described once (as HOOMD-blue's
// param_type). PairDPDBase derives from the description pair_coeff's parsing and its messages,
// the restart record of a type pair, write_data, init_one's symmetry and extract().
#ifndef ETD_PAIR_COEFF_DESCRIPTION_H
#define ETD_PAIR_COEFF_DESCRIPTION_H

namespace etd {

// How pair_coeff gives the value, after I J: required and optional positional values in the
// description's order (required ones first), then "keyword value" pairs in any order.
enum class CoeffArg { Required, Optional, Keyword };
enum class CoeffBound { Any, NonNegative, Positive };

// Where a value not given in pair_coeff comes from.
constexpr int DEFAULT_VALUE = -1;     // default_value
constexpr int DEFAULT_CUTOFF = -2;    // pair_style's cutoff (reset by a new pair_style)

struct CoeffParam {
  const char *name;    // in pair_coeff's usage line; the keyword itself for a keyword
  const char *what;    // in its error messages ("dissipative exponent s")
  CoeffArg arg;
  CoeffBound bound;
  // DEFAULT_VALUE, DEFAULT_CUTOFF, or the index of the parameter whose value it takes (then
  // whether it was given is kept beside it, and in the restart record)
  int default_from;
  double default_value;
  bool range;                  // a cutoff: the type pair interacts up to the largest of these
  const char *value_name;      // a keyword's value in the usage line ("rcD")
  const char *extract_name;    // its name for Pair::extract, nullptr for none
};

// The parameters in the order of the restart record (doubles, then one int per parameter that
// defaults to another); exactly one has default_from DEFAULT_CUTOFF: the pair's cutoff.
struct CoeffDescription {
  const char *style;    // pair style name, for the messages
  const CoeffParam *params;
  int count;
};

}    // namespace etd

#endif

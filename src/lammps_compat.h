// ETD-DPD: the one place that hides differences between LAMMPS versions.
//
// ETD_LAMMPS_VERSION (yyyymmdd) is derived by CMake from the tree's version.h. The 2022 API
// changes (neighbor->add_request, comm->forward_comm(this)/reverse_comm(this)) are selected by
// it; CMake also detects them in the headers and passes ETD_LAMMPS_HAS_* explicitly, so a
// development snapshot between releases builds too.
#ifndef ETD_LAMMPS_COMPAT_H
#define ETD_LAMMPS_COMPAT_H

#include "comm.h"
#include "domain.h"
#include "fix.h"
#include "neigh_request.h"
#include "neighbor.h"

#ifndef ETD_LAMMPS_VERSION
#error "ETD_LAMMPS_VERSION must be defined by the build system (derived from version.h)"
#endif
#ifndef ETD_LAMMPS_HAS_ADD_REQUEST
#define ETD_LAMMPS_HAS_ADD_REQUEST (ETD_LAMMPS_VERSION >= 20220504)
#endif
#ifndef ETD_LAMMPS_HAS_CHECKED_MINIMUM_IMAGE
#define ETD_LAMMPS_HAS_CHECKED_MINIMUM_IMAGE (ETD_LAMMPS_VERSION >= 20230802)
#endif
#ifndef ETD_LAMMPS_HAS_GENERIC_COMM
#define ETD_LAMMPS_HAS_GENERIC_COMM (ETD_LAMMPS_VERSION >= 20220623)
#endif

namespace etd {
namespace compat {

  // Stock fix wall/reflect/stochastic crashes at its first step from this LAMMPS version on (it
  // records a dump-image plane in an array only its parent fix wall/reflect allocates); seen in
  // 4 Jul 2026. A run-time number: the plugin may be loaded by a LAMMPS other than the one it
  // was built against.
  constexpr int first_version_with_crashing_wall_reflect_stochastic = 20260704;

  // A neighbor request as its requestor may amend it until LAMMPS processes the requests
  // (Neighbor::init, after every pair, fix and compute init).
#if ETD_LAMMPS_HAS_ADD_REQUEST
  using NeighRequestHandle = LAMMPS_NS::NeighRequest *;
#else
  using NeighRequestHandle = int;    // the index in neighbor->requests
#endif

  // A half neighbor list with the default newton setting, as a plain pair style uses.
  template <typename Requestor>
  inline NeighRequestHandle request_half_list(LAMMPS_NS::Neighbor *neighbor, Requestor *requestor,
                                              int instance)
  {
#if ETD_LAMMPS_HAS_ADD_REQUEST
    (void) instance;
    return neighbor->add_request(requestor);
#else
    return neighbor->request(requestor, instance);
#endif
  }

  // Turns a request made this init into a newton-off list whatever the newton setting.
  inline void make_request_newton_off(LAMMPS_NS::Neighbor *neighbor, NeighRequestHandle request)
  {
#if ETD_LAMMPS_HAS_ADD_REQUEST
    (void) neighbor;
    request->apply_flags(LAMMPS_NS::NeighConst::REQ_NEWTON_OFF);
#else
    neighbor->requests[request]->newton = 2;
#endif
  }

  // the request's list built only on demand (Neighbor::build_one), not at each reneighboring
  inline void make_request_occasional(LAMMPS_NS::Neighbor *neighbor, NeighRequestHandle request)
  {
#if ETD_LAMMPS_HAS_ADD_REQUEST
    (void) neighbor;
    request->apply_flags(LAMMPS_NS::NeighConst::REQ_OCCASIONAL);
#else
    neighbor->requests[request]->occasional = 1;
#endif
  }

  // A perpetual half neighbor list for a fix: the default newton setting, or with newton_off
  // newton off whatever the setting (a pair of an owned and a ghost atom is then listed on the
  // owned atom's side by every rank that owns one of the two, and twice on one rank where the
  // ghost is an image of an atom it owns).
  inline void request_fix_half_list(LAMMPS_NS::Neighbor *neighbor, LAMMPS_NS::Fix *fix,
                                    int instance, bool newton_off = false)
  {
#if ETD_LAMMPS_HAS_ADD_REQUEST
    (void) instance;
    neighbor->add_request(fix,
                          newton_off ? LAMMPS_NS::NeighConst::REQ_NEWTON_OFF
                                     : LAMMPS_NS::NeighConst::REQ_DEFAULT);
#else
    const int irequest = neighbor->request(fix, instance);
    neighbor->requests[irequest]->pair = 0;
    neighbor->requests[irequest]->fix = 1;
    if (newton_off) neighbor->requests[irequest]->newton = 2;
#endif
  }

  // Reverse communication of a pair style's per-atom data (pack/unpack_reverse_comm).
  inline void reverse_comm(LAMMPS_NS::Comm *comm, LAMMPS_NS::Pair *pair)
  {
#if ETD_LAMMPS_HAS_GENERIC_COMM
    comm->reverse_comm(pair);
#else
    comm->reverse_comm_pair(pair);
#endif
  }

  // The minimum-image convention for a separation (newer LAMMPS takes the caller's file and
  // line for its error on atoms too far apart).
  inline void minimum_image(LAMMPS_NS::Domain *domain, double delta[3])
  {
#if ETD_LAMMPS_HAS_CHECKED_MINIMUM_IMAGE
    domain->minimum_image(FLERR, delta[0], delta[1], delta[2]);
#else
    domain->minimum_image(delta[0], delta[1], delta[2]);
#endif
  }
  inline void forward_comm(LAMMPS_NS::Comm *comm, LAMMPS_NS::Pair *pair)
  {
#if ETD_LAMMPS_HAS_GENERIC_COMM
    comm->forward_comm(pair);
#else
    comm->forward_comm_pair(pair);
#endif
  }

  inline void forward_comm(LAMMPS_NS::Comm *comm, LAMMPS_NS::Fix *fix)
  {
#if ETD_LAMMPS_HAS_GENERIC_COMM
    comm->forward_comm(fix);
#else
    comm->forward_comm_fix(fix);
#endif
  }

}    // namespace compat
}    // namespace etd

#endif

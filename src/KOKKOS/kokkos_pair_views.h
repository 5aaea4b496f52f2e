// ETD-DPD: the KOKKOS package's types of the views a pair style holds, under the names of the
// LAMMPS at hand. LAMMPS renamed them when its KOKKOS package gained a choice of precision
// (KK_FLOAT for positions and coefficients, KK_ACC_FLOAT for sums: LAMMPS 4Jul2026 has them,
// 4Feb2025 not); cmake/LammpsVersion.cmake finds which names the headers use
// (ETD_LAMMPS_HAS_KK_FLOAT). The package's styles compute in double precision, LAMMPS's
// default, and refuse to build against another.
#ifndef ETD_KOKKOS_PAIR_VIEWS_H
#define ETD_KOKKOS_PAIR_VIEWS_H

#include "kokkos_type.h"

#include <type_traits>

#ifndef ETD_LAMMPS_HAS_KK_FLOAT
#error "ETD_LAMMPS_HAS_KK_FLOAT is set by cmake/LammpsVersion.cmake"
#endif

namespace LAMMPS_NS {

#if ETD_LAMMPS_HAS_KK_FLOAT
static_assert(std::is_same_v<KK_FLOAT, double> && std::is_same_v<KK_ACC_FLOAT, double>,
              "the ETD-DPD /kk styles need LAMMPS's KOKKOS package in double precision "
              "(CMake KOKKOS_PREC=double, the default)");
#endif

template <class DeviceType> struct KokkosPairViews {
  using AT = ArrayTypes<DeviceType>;
#if ETD_LAMMPS_HAS_KK_FLOAT
  using x_randomread = typename AT::t_kkfloat_1d_3_lr_randomread;
  using v_randomread = typename AT::t_kkfloat_1d_3_randomread;
  using f_array = typename AT::t_kkacc_1d_3;
  using f_layout = typename DAT::t_kkacc_1d_3::array_layout;
  using eatom = typename AT::t_kkacc_1d;
  using eatom_dual = DAT::ttransform_kkacc_1d;
  using eatom_layout = typename DAT::t_kkacc_1d::array_layout;
  using vatom = typename AT::t_kkacc_1d_6;
  using vatom_dual = DAT::ttransform_kkacc_1d_6;
  using vatom_layout = typename DAT::t_kkacc_1d_6::array_layout;
  using cutsq = typename AT::t_kkfloat_2d;
  using cutsq_dual = DAT::ttransform_kkfloat_2d;
#else
  using x_randomread = typename AT::t_x_array_randomread;
  using v_randomread = typename AT::t_x_array_randomread;
  using f_array = typename AT::t_f_array;
  using f_layout = typename DAT::t_f_array::array_layout;
  using eatom = typename AT::t_efloat_1d;
  using eatom_dual = DAT::tdual_efloat_1d;
  using eatom_layout = typename DAT::t_efloat_1d::array_layout;
  using vatom = typename AT::t_virial_array;
  using vatom_dual = DAT::tdual_virial_array;
  using vatom_layout = typename DAT::t_virial_array::array_layout;
  using cutsq = typename AT::t_ffloat_2d;
  using cutsq_dual = typename AT::tdual_ffloat_2d;
#endif
};

}    // namespace LAMMPS_NS

#endif

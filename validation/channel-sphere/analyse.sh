#!/bin/bash
# Tables and figures of validation/channel-sphere/README.md from the drag, wall-radius and profile
# files of the runs: the tables into results/tables.txt (and on the screen), the figures into
# figures/. Run from anywhere: bash validation/channel-sphere/analyse.sh
# (system Python with numpy and matplotlib). The files are kept in one JSON file,
# results/records.json, and written out into results/ where a run has not left its own (the logs
# and the files themselves are not kept in the repository). After new runs, merge their files in:
#   python/study_records.py pack validation/channel-sphere/results validation/channel-sphere/results/records.json
set -e -o pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/results"
PY=${PY:-/usr/bin/python3}
$PY ../../../python/study_records.py unpack records.json . > /dev/null
{
T=../../../python/channel_sphere.py
F=../figures
echo "== shear flow, 56-particle sphere and one-particle colloid (U = mean fluid velocity)"
$PY $T drag --series "56 particles:drag.U0.15,drag.U0.25,drag.U0.5,drag.U0.9" \
    --series "56 particles, paper's box:drag.U0.9_full" --series "56 particles, paper's length:drag.U0.5_nx120,drag.U0.9_nx120" \
    --series "56 particles, a_sphere 18.75:drag.U0.9_a18.75" \
    --series "1 particle, rcC 1.5:drag.colloid_U0.9" --series "1 particle, rcC 1.22:drag.colloid_U0.9_rc1.22" \
    --series "1 particle, rcC 1.1:drag.colloid_U0.9_rc1.1" \
    --series "1 particle, rcC 1.22, paper's box:drag.colloid_U0.9_rc1.22_full" \
    --series "1 particle dpd/fpm, rc 1.54:drag.colloid_fpm_U0.9_rc1.54" \
    --title "sphere between moving walls (reduced box and paper's box)" \
    --png $F/channel_sphere_cd_shear.png
echo "== the same, total force instead of the conservative + dissipative part"
$PY $T drag --force total drag.U0.15 drag.U0.25 drag.U0.5 drag.U0.9 drag.U0.9_full drag.U0.9_nx120 drag.U0.5_nx120 drag.U0.9_a18.75 drag.colloid_U0.9 drag.colloid_U0.9_rc1.22 drag.colloid_U0.9_rc1.22_full drag.colloid_U0.9_rc1.1 drag.colloid_fpm_U0.9_rc1.54
echo "== dpd/fpm colloid calibration runs (2,000 steps after 500; 5 batches)"
$PY $T drag --discard 0.15 --batches 5 drag.colloid_fpm_cal_rc1.8_a200 drag.colloid_fpm_cal_rc1.5_a200
echo "== rigid cylindrical channel, body force (U = mean fluid velocity)"
$PY $T drag --series "d/D=0.19:drag.D15.75_f0.016,drag.D15.75_f0.032" --series "d/D=0.25:drag.D12_f0.027,drag.D12_f0.054" \
    --series "d/D=0.33:drag.D9_f0.045,drag.D9_f0.09" --series "between walls:drag.U0.15,drag.U0.25,drag.U0.5,drag.U0.9" \
    --title "sphere on the axis of a rigid pipe (length 25.2)" \
    --png $F/channel_sphere_cd_pipe.png
echo "== rigid pipes, one-particle dpd/gen colloid (rcC = 1.22) against the 56-particle sphere (section 3.1)"
$PY $T drag drag.D15.75_f0.032 drag.D15.75_f0.032_colloid_rc1.22 drag.D12_f0.054 drag.D12_f0.054_colloid_rc1.22 \
    drag.D9_f0.09 drag.D9_f0.09_colloid_rc1.22
echo "== rigid pipes, one-particle dpd/fpm colloid (rc = 1.54, every pair dpd/fpm; section 3.2)"
$PY $T drag drag.D15.75_f0.032_fpm_rc1.54 drag.D12_f0.054_fpm_rc1.54 drag.D9_f0.09_fpm_rc1.54
echo "== the sphere's hydrodynamic radius a_h: the Stokes radius with the wall factor taken out (section 3.3)"
echo "-- free flow: Faxen's factor midway between walls 6.3 from the centre"
$PY $T drag --slit 6.3 drag.U0.15 drag.U0.25 drag.U0.5 drag.U0.9 drag.U0.9_a18.75 drag.U0.9_full drag.U0.9_nx120 drag.U0.5_nx120 \
    drag.colloid_U0.9_rc1.22 drag.colloid_U0.9_rc1.22_full drag.colloid_fpm_U0.9_rc1.54
echo "-- pipes: Haberman and Sayre's factor for Poiseuille flow, centre-line velocity 2 U, tube radius D/2"
$PY $T drag --tube 7.875 drag.D15.75_f0.016 drag.D15.75_f0.032 drag.D15.75_f0.032_colloid_rc1.22 drag.D15.75_f0.032_fpm_rc1.54
$PY $T drag --tube 6 drag.D12_f0.027 drag.D12_f0.054 drag.D12_f0.054_colloid_rc1.22 drag.D12_f0.054_fpm_rc1.54
$PY $T drag --tube 4.5 drag.D9_f0.045 drag.D9_f0.09 drag.D9_f0.09_colloid_rc1.22 drag.D9_f0.09_fpm_rc1.54
echo "-- in.sphere_compliant, D = 9: measured centre-line velocity, each wall's own fitted R_h (fit r < 4, section 4.5)"
$PY $T drag --velocity v_vcentre --centre-line --tube 5.255 drag.d33_rigid_f0.03 drag.d33_rigid_f0.06+drag.d33_rigid_f0.06_s2
$PY $T drag --velocity v_vcentre --centre-line --tube 5.141 drag.d33_H8_f0.03 drag.d33_H8_f0.06+drag.d33_H8_f0.06_s2
$PY $T drag --velocity v_vcentre --centre-line --tube 5.203 drag.d33_H2_f0.03 drag.d33_H2_f0.06+drag.d33_H2_f0.06_s2
$PY $T drag --velocity v_vcentre --centre-line --tube 5.160 drag.d33_H1_f0.03 drag.d33_H1_f0.06+drag.d33_H1_f0.06_s2
$PY $T drag --velocity v_vcentre --centre-line --tube 5.175 drag.d33_H8_rmax1.02_f0.06+drag.d33_H8_rmax1.02_f0.06_s2
$PY $T drag --velocity v_vcentre --centre-line --tube 6.11 drag.d33_alike_rigid_f0.06
$PY $T drag --velocity v_vcentre --centre-line --tube 4.77 drag.d33_alike_H1_f0.06
echo "-- the frozen shell with the built radius D/2 = 4.5 instead of R_h"
$PY $T drag --velocity v_vcentre --centre-line --tube 4.5 drag.d33_rigid_f0.03 drag.d33_rigid_f0.06+drag.d33_rigid_f0.06_s2
echo "== compliant channel (d/D = 0.24, r_max = 3); U = mean velocity of the fluid inside r < D/2"
$PY $T drag --velocity v_vcore drag.compliant_H8_rmax3_rigidyes drag.compliant_H1_rmax3_rigidno \
    drag.compliant_H8_rmax3_rigidno_r2
echo "== wall radius, mean of the blocks after the first 20 %"
$PY $T radius wall_radius.compliant_H1_rmax3_rigidno wall_radius.compliant_H8_rmax3_rigidno_r2 \
    wall_radius.compliant_H8_rmax3_rigidyes
echo "== wall radius, every block (the wall is still moving)"
$PY $T radius --each --discard 0 wall_radius.compliant_H1_rmax3_rigidno --png $F/channel_sphere_radius_H1.png
$PY $T radius --each --discard 0 wall_radius.compliant_H8_rmax3_rigidno_r2 --png $F/channel_sphere_radius_H8.png
echo "== compliant channel, springs with rest length (fene/expand); U = core fluid velocity"
$PY $T drag --velocity v_vcore drag.compliant_H8_rmax3_rigidyes drag.compliant_H1_rmax3_rigidno_rest \
    drag.compliant_H8_rmax3_rigidno_rest drag.compliant_H8_rmax3_rigidno_rest_diag \
    drag.compliant_H1_rmax3_rigidno_rest_diag_outer \
    drag.compliant_H8_rmax3_rigidno_rest_diag_outer
$PY $T drag --velocity v_vcore --series "frozen shell:drag.compliant_H8_rmax3_rigidyes" \
    --series "H=8, outer layer anchored:drag.compliant_H8_rmax3_rigidno_rest_diag_outer" \
    --series "H=1, outer layer anchored:drag.compliant_H1_rmax3_rigidno_rest_diag_outer" \
    --series "H=8, r_max=1.02, outer layer anchored:drag.compliant_H8_rmax1.02_rigidno_rest_diag_outer" \
    --title "compliant channel d/D = 0.24, r_max = 3 (length 25.2)" --png $F/channel_sphere_cd_compliant.png
echo "== wall radius, springs with rest length"
$PY $T radius wall_radius.compliant_H1_rmax3_rigidno_rest wall_radius.compliant_H8_rmax3_rigidno_rest \
    wall_radius.compliant_H8_rmax3_rigidno_rest_diag \
    wall_radius.compliant_H1_rmax3_rigidno_rest_diag_outer wall_radius.compliant_H8_rmax3_rigidno_rest_diag_outer \
    wall_radius.compliant_H8_rmax3_rigidyes
$PY $T radius wall_radius.compliant_H1_rmax3_rigidno_rest_diag_outer wall_radius.compliant_H8_rmax3_rigidno_rest_diag_outer \
    wall_radius.compliant_H8_rmax1.02_rigidno_rest_diag_outer wall_radius.compliant_H8_rmax3_rigidyes --png $F/channel_sphere_radius_outer.png
$PY $T radius --each --discard 0 wall_radius.compliant_H8_rmax3_rigidno_rest_diag --png $F/channel_sphere_radius_H8_diag_ends.png
echo "== compliant channel, longer runs (seed 3001, 24,000 steps) and pooled with the first runs (section 4.3)"
$PY $T drag --velocity v_vcore drag.long_rigid drag.long_H8_rmax3_outer drag.long_H1_rmax3_outer drag.long_H8_rmax1.02_outer \
    drag.long_rigid+drag.compliant_H8_rmax3_rigidyes \
    drag.long_H8_rmax3_outer+drag.compliant_H8_rmax3_rigidno_rest_diag_outer \
    drag.long_H1_rmax3_outer+drag.compliant_H1_rmax3_rigidno_rest_diag_outer \
    drag.long_H8_rmax1.02_outer+drag.compliant_H8_rmax1.02_rigidno_rest_diag_outer
$PY $T drag --velocity v_vcore --series "frozen shell:drag.long_rigid+drag.compliant_H8_rmax3_rigidyes" \
    --series "H=8:drag.long_H8_rmax3_outer+drag.compliant_H8_rmax3_rigidno_rest_diag_outer" \
    --series "H=1:drag.long_H1_rmax3_outer+drag.compliant_H1_rmax3_rigidno_rest_diag_outer" \
    --series "H=8, r_max=1.02:drag.long_H8_rmax1.02_outer+drag.compliant_H8_rmax1.02_rigidno_rest_diag_outer" \
    --title "compliant channel, outer layer anchored, 2 runs pooled" --png $F/channel_sphere_cd_compliant_pooled.png
$PY $T radius wall_radius.long_rigid wall_radius.long_H8_rmax3_outer wall_radius.long_H1_rmax3_outer wall_radius.long_H8_rmax1.02_outer
echo "== ends-anchored wall without flow: paper's wall particles against wall particles repelling like fluid (section 4.1)"
$PY $T radius --each --discard 0 wall_radius.noflow_H8_rmax3_diag_ends wall_radius.noflow_alike_H8_rmax3_diag_ends
for f in drag.noflow_H8_rmax3_diag_ends drag.noflow_alike_H8_rmax3_diag_ends; do
    echo "$f:"; awk '!/^#/ && $1 % 1000 == 0 {printf "  %d %.3f %.0f\n", $1, $13, $12}' $f
done
echo "== ends-anchored wall with flow, wall particles repelling like fluid (section 4.1)"
$PY $T radius --each --discard 0 wall_radius.alike_H8_rmax3_diag_ends wall_radius.alike_H1_rmax3_diag_ends
for f in drag.alike_rigid drag.alike_H8_rmax3_diag_ends drag.alike_H1_rmax3_diag_ends; do
    echo "$f:"; awk '!/^#/ && $1 % 1000 == 0 {printf "  %d %.3f %.0f\n", $1, $13, $12}' $f
done
echo "== core velocity and core fluid count against time (steps, v_vcore, v_ncore), every 1000 steps"
for f in drag.compliant_H8_rmax3_rigidyes drag.compliant_H1_rmax3_rigidno drag.compliant_H8_rmax3_rigidno_r2 \
         drag.compliant_H1_rmax3_rigidno_rest drag.compliant_H8_rmax3_rigidno_rest drag.compliant_H8_rmax3_rigidno_rest_diag \
         drag.compliant_H1_rmax3_rigidno_rest_diag_outer \
         drag.compliant_H8_rmax3_rigidno_rest_diag_outer drag.compliant_H8_rmax1.02_rigidno_rest_diag_outer; do
    echo "$f:"; awk '!/^#/ && $1 % 1000 == 0 {printf "  %d %.3f %.0f\n", $1, $13, $12}' $f
done
echo "== compliant channel, one-particle dpd/gen colloid (rcC = 1.22) against the 56-particle sphere (section 4.4)"
$PY $T drag --velocity v_vcore drag.colloid_rigid drag.colloid_H8_rmax3_outer drag.colloid_H1_rmax3_outer \
    drag.long_rigid+drag.compliant_H8_rmax3_rigidyes \
    drag.long_H8_rmax3_outer+drag.compliant_H8_rmax3_rigidno_rest_diag_outer \
    drag.long_H1_rmax3_outer+drag.compliant_H1_rmax3_rigidno_rest_diag_outer
$PY $T radius wall_radius.colloid_rigid wall_radius.colloid_H8_rmax3_outer wall_radius.colloid_H1_rmax3_outer
echo "== compliant channel, one-particle dpd/fpm colloid (rc = 1.54, every pair dpd/fpm; section 4.4)"
$PY $T drag --velocity v_vcore drag.fpm_rigid drag.fpm_H8_rmax3_outer
$PY $T radius wall_radius.fpm_rigid wall_radius.fpm_H8_rmax3_outer
echo "== compliant channel d/D = 0.33 (D = 9), outer layer anchored: four walls, two forces (section 4.5)"
for v in v_vcore v_vcentre; do
$PY $T drag --velocity $v drag.d33_rigid_f0.03 drag.d33_H8_f0.03 drag.d33_H2_f0.03 drag.d33_H1_f0.03 \
    drag.d33_rigid_f0.06+drag.d33_rigid_f0.06_s2 drag.d33_H8_f0.06+drag.d33_H8_f0.06_s2 \
    drag.d33_H2_f0.06+drag.d33_H2_f0.06_s2 drag.d33_H1_f0.06+drag.d33_H1_f0.06_s2
done
$PY $T drag --velocity v_vcore --series "frozen shell:drag.d33_rigid_f0.03,drag.d33_rigid_f0.06+drag.d33_rigid_f0.06_s2" \
    --series "H=8:drag.d33_H8_f0.03,drag.d33_H8_f0.06+drag.d33_H8_f0.06_s2" \
    --series "H=2:drag.d33_H2_f0.03,drag.d33_H2_f0.06+drag.d33_H2_f0.06_s2" \
    --series "H=1:drag.d33_H1_f0.03,drag.d33_H1_f0.06+drag.d33_H1_f0.06_s2" \
    --title "compliant channel d/D = 0.33, r_max = 3, outer layer anchored" --png $F/channel_sphere_cd_compliant_d33.png
$PY $T radius --near 2.5 wall_radius.d33_rigid_f0.03 wall_radius.d33_H8_f0.03 wall_radius.d33_H2_f0.03 wall_radius.d33_H1_f0.03 \
    wall_radius.d33_rigid_f0.06 wall_radius.d33_H8_f0.06 wall_radius.d33_H2_f0.06 wall_radius.d33_H1_f0.06 \
    wall_radius.d33_rigid_f0.06_s2 wall_radius.d33_H8_f0.06_s2 wall_radius.d33_H2_f0.06_s2 wall_radius.d33_H1_f0.06_s2
$PY $T velocity velocity_profile.d33_rigid_f0.03 velocity_profile.d33_H8_f0.03 velocity_profile.d33_H2_f0.03 velocity_profile.d33_H1_f0.03
$PY $T velocity velocity_profile.d33_rigid_f0.06_s2 velocity_profile.d33_H8_f0.06_s2 velocity_profile.d33_H2_f0.06 \
    velocity_profile.d33_H2_f0.06_s2 velocity_profile.d33_H1_f0.06_s2
$PY $T velocity --fit 4 velocity_profile.d33_rigid_f0.03 velocity_profile.d33_H8_f0.03 velocity_profile.d33_H2_f0.03 velocity_profile.d33_H1_f0.03 \
    velocity_profile.d33_H2_f0.06
$PY $T velocity --fit 4 velocity_profile.d33_rigid_f0.06_s2 velocity_profile.d33_H8_f0.06_s2 \
    velocity_profile.d33_H2_f0.06_s2 velocity_profile.d33_H1_f0.06_s2 --png $F/channel_sphere_velocity_d33.png
echo "== wall factor the inner layer's shift would give at a fixed centre-line velocity (tube radius D/2 + shift near the sphere)"
$PY $T tube 4.5 4.60 4.85 4.94
echo "== number density of wall and fluid particles per ring, slabs away from the sphere (seed 3001 runs, force 0.06)"
$PY $T density --rmin 3.5 --rmax 6.5 "wall, frozen shell=wall_profile.d33_rigid_f0.06_s2" "wall, H = 8=wall_profile.d33_H8_f0.06_s2" \
    "wall, H = 2=wall_profile.d33_H2_f0.06_s2" "wall, H = 1=wall_profile.d33_H1_f0.06_s2"
$PY $T density --rmin 3.5 --rmax 6.5 "fluid, frozen shell=velocity_profile.d33_rigid_f0.06_s2" "fluid, H = 8=velocity_profile.d33_H8_f0.06_s2" \
    "fluid, H = 2=velocity_profile.d33_H2_f0.06_s2" "fluid, H = 1=velocity_profile.d33_H1_f0.06_s2"
$PY $T density --rmin 3 --rmax 6.5 "wall, frozen shell=wall_profile.d33_rigid_f0.06_s2" "wall, H = 1=wall_profile.d33_H1_f0.06_s2" \
    "fluid, frozen shell=velocity_profile.d33_rigid_f0.06_s2" "fluid, H = 1=velocity_profile.d33_H1_f0.06_s2" \
    --png $F/channel_sphere_density_d33.png
echo "== d/D = 0.33, wall particles repelling like fluid (a_fw = a_wall = 18.75), force 0.06 (section 4.5)"
for v in v_vcore v_vcentre; do
$PY $T drag --velocity $v drag.d33_alike_rigid_f0.06 drag.d33_alike_H1_f0.06
done
$PY $T radius --near 2.5 wall_radius.d33_alike_rigid_f0.06 wall_radius.d33_alike_H1_f0.06
$PY $T velocity --fit 4 velocity_profile.d33_alike_rigid_f0.06 velocity_profile.d33_alike_H1_f0.06
$PY $T density --rmin 3.5 --rmax 6.5 "wall, frozen=wall_profile.d33_alike_rigid_f0.06" "wall, H = 1=wall_profile.d33_alike_H1_f0.06" \
    "fluid, frozen=velocity_profile.d33_alike_rigid_f0.06" "fluid, H = 1=velocity_profile.d33_alike_H1_f0.06"
for f in drag.d33_alike_rigid_f0.06 drag.d33_alike_H1_f0.06; do
    echo "$f:"; awk '!/^#/ && $1 % 2000 == 0 {printf "  %d %.3f %.0f\n", $1, $13, $12}' $f
done
$PY $T tube 4.5 4.69
echo "== d/D = 0.33, H = 8, r_max = 1.02 against r_max = 3, force 0.06, two seeds pooled (section 4.5)"
for v in v_vcore v_vcentre; do
$PY $T drag --velocity $v drag.d33_H8_rmax1.02_f0.06+drag.d33_H8_rmax1.02_f0.06_s2 drag.d33_H8_f0.06+drag.d33_H8_f0.06_s2
done
$PY $T radius --near 2.5 wall_radius.d33_H8_rmax1.02_f0.06 wall_radius.d33_H8_rmax1.02_f0.06_s2
$PY $T velocity --fit 4 velocity_profile.d33_H8_rmax1.02_f0.06 velocity_profile.d33_H8_rmax1.02_f0.06_s2
$PY $T density --rmin 3.7 --rmax 6.2 "wall, r_max 1.02=wall_profile.d33_H8_rmax1.02_f0.06_s2" "wall, r_max 3=wall_profile.d33_H8_f0.06_s2"
echo "== section 6: the viscosity of this fluid by reverse Poiseuille (viscosity.sh)"
cat viscosity/fits.txt
echo "== section 6: the paper's length with profiles; half the step in the reduced box"
$PY $T drag drag.U0.9_nx120_profiles drag.U0.9 drag.U0.9_dt0.005
$PY $T drag --force total drag.U0.9 drag.U0.9_dt0.005
$PY $T shells profiles.U0.9_nx120_profiles --discard 0
$PY $T shells profiles.U0.9_nx120_profiles --discard 0 --fit-from 2.5 --fit-to 5
$PY $T line line.U0.9_nx120_profiles --discard 0
} | tee tables.txt

#pragma once
// Stress by eq. 2.25, first line: kinetic part about the mean velocity plus the pair
// virial, sigma = -(1/V) [ sum m (v - v~)(v - v~) + 1/2 sum_ab r_ab f_ab ].
// Cauchy sign: tension positive, compression negative (minus LAMMPS's pressure tensor).
// Results in eV/Angstrom^3 (multiply by units::eV_per_A3_in_GPa for GPa).
#include <vector>

#include "mpmx/md/forces.hpp"
#include "mpmx/md/particles.hpp"

namespace mpmx::md {

// Atoms with on-step velocities (eq. 5.6) and positions in the fundamental box.
Mat3 box_stress(const Atoms& atoms, const std::vector<double>& type_mass, const Sym6& virial,
                double volume);

// Stress in nbins slabs of equal width along x (1-D samples); virial_atom holds 6 per
// atom (half of each pair to each atom). Each slab's kinetic part is about its own mean.
std::vector<Mat3> slab_stress(const Atoms& atoms, const std::vector<double>& type_mass,
                              const std::vector<double>& virial_atom, const Box& box, int nbins);

// Slabs over [x0, x1) only (a bar between walls), each of volume (x1-x0)/nbins ly lz;
// atoms outside are ignored.
std::vector<Mat3> slab_stress(const Atoms& atoms, const std::vector<double>& type_mass,
                              const std::vector<double>& virial_atom, const Box& box, int nbins,
                              double x0, double x1);

// Each atom's share of the box stress, over the mean volume an atom holds (V/N): 6 per
// atom (xx yy zz xy xz yz), the kinetic part about the whole box's mean velocity; their
// mean is box_stress. LAMMPS's compute stress/atom is the same times -V/N (pressure
// times volume), and OVITO reads it as such.
std::vector<double> atom_stress(const Atoms& atoms, const std::vector<double>& type_mass,
                                const std::vector<double>& virial_atom, double volume);

// Stress in nx x ny columns over x and y (2-D samples), index ix + nx * iy.
std::vector<Mat3> column_stress(const Atoms& atoms, const std::vector<double>& type_mass,
                                const std::vector<double>& virial_atom, const Box& box, int nx,
                                int ny);

}  // namespace mpmx::md

#pragma once
// An elastic disk thrown at a fixed wall (2-D, 20 x 20 cells, dt 0.01 to t = 5, a record
// every 100 steps into vtk/): the energy-growth tests' deck and the output folder's 2-D run.
namespace mpmx::test {

inline constexpr const char* kDiskOnWall = R"(
[case]
id = "disk_on_wall"
title = "an elastic disk hits a wall"
[grid]
dim = 2
lower = [0.0, 0.0]
upper = [1.0, 1.0]
cells = [20, 20]
[particles]
per_cell = [2, 2]
[[body]]
shape = "circle"
center = [0.3, 0.5]
radius = 0.2
velocity = [-0.1, 0.0]
[scheme]
name = "mpm"
[material]
model = "linear_elastic"
density = 1000.0
youngs_modulus = 1000.0
poisson_ratio = 0.3
[boundary]
x_lower = { type = "fixed" }
[time]
dt = 0.01
end = 5.0
[output]
every = 100
)";

}  // namespace mpmx::test

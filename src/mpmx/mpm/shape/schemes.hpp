#pragma once
// The shape schemes a deck names ([scheme] name = ...): one line each, in the order of
// the Scheme ids (scheme.hpp). An entry is a struct with its name, what the step needs
// to know of it (tracks_domain, ddmp, subpoints), how far its entries reach and how it
// fills one particle's (stencil_build.hpp).
#include "mpmx/core/registry.hpp"
#include "mpmx/mpm/shape/cpdi_scheme.hpp"
#include "mpmx/mpm/shape/ddmp_scheme.hpp"
#include "mpmx/mpm/shape/ddmp_subpoints_scheme.hpp"
#include "mpmx/mpm/shape/gimp_scheme.hpp"
#include "mpmx/mpm/shape/mpm_scheme.hpp"

namespace mpmx::mpm::shape {

using Schemes = Registry<MpmScheme, UgimpScheme, CpgimpScheme, CpdiScheme, DdmpScheme, DdmpSubpointsScheme>;

}  // namespace mpmx::mpm::shape

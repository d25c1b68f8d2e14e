// The keys of a 3D problem file (`dimension: 3`): one body meshed with hexahedra.
#pragma once

#include "hpcontact/io/input_schema.hpp"

namespace hpcontact::io {

/// Most hexahedron degree per direction a 3D problem may ask for.
constexpr int kMaxHexDegree = 12;

/// Every key of a 3D problem file, in the form of input_schema().
const Schema& solid_schema();

}  // namespace hpcontact::io

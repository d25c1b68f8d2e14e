// libFuzzer target: the Gmsh MSH 4.1 reader and the import of a body from what it accepts: a 2D
// body (every quadrilateral, arcs recovered from midside nodes, edge sets from physical lines) and
// a 3D one (every hexahedron, face sets from physical surfaces), each input read both ways.
// Refusal with an hpcontact::Error is fine; a crash, a sanitizer report, another exception
// or a hang is a finding.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "hpcontact/core/error.hpp"
#include "hpcontact/io/gmsh_hex_import.hpp"
#include "hpcontact/io/gmsh_import.hpp"
#include "hpcontact/io/gmsh_reader.hpp"

using namespace hpcontact;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const io::GmshMesh mesh = io::parse_gmsh(text, "fuzz.msh");
    io::ImportOptions options;
    (void)io::import_gmsh_body(mesh, options);
  } catch (const Error&) {
    // refused with a message: fine
  }
  try {
    (void)io::import_gmsh_hex_body(io::parse_gmsh_volume(text, "fuzz.msh"));
  } catch (const Error&) {
  }
  return 0;
}

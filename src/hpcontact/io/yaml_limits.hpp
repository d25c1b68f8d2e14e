// Bounds on the YAML an input is made of, checked before yaml-cpp builds its tree: the text's
// bytes and the values the tree would hold.
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace hpcontact::io {

/// Largest YAML text read (bytes): a problem or study file, a problem given to the Python module
/// as a string, a --set value. Text that builds no tree (comments, long scalars) costs some
/// 5 bytes of memory and 0.2 s per MB.
constexpr std::size_t kMaxYamlBytes = 16u << 20;

/// Most values of the YAML tree of a problem or study (file, --set values and the meshes of its
/// Gmsh files): every scalar, list, map and empty value counts one, an alias the values of what
/// it repeats. yaml-cpp keeps some 500 bytes of memory per value: `check` of a problem at the
/// limit took 590 MB and 4.5 s of CPU. An inline or Gmsh mesh takes about 4 values per node and
/// 6 per element, so some 10⁵ elements fit.
constexpr std::size_t kMaxYamlValues = 1'000'000;

/// Why a YAML text is refused before its tree is built, and where.
struct YamlBound {
  YAML::Mark mark;   ///< 0-based line and column of the value at which the bound was passed
  std::string what;  ///< the cause and what to do, without a place
};

/// Counts the values of `text` (one YAML document, as yaml-cpp's own parser reads it, keeping no
/// tree: its memory does not grow with the text), stopping at the first value beyond `most`
/// (kMaxYamlValues, or what the rest of a tree leaves a --set value) or at an alias inside the
/// list or map it names (a cycle). `what` names the text in the message ("problem file",
/// "--set value"). Nothing if the text is within the bounds; throws YAML::ParserException
/// (YAML::DeepRecursion for nesting too deep) as YAML::Load would.
std::optional<YamlBound> exceeded_yaml_bound(std::string_view text, const std::string& what,
                                             std::size_t most = kMaxYamlValues);

/// "the <what> is larger than the 16 MB it may have (19.6 MB)" if `bytes` > kMaxYamlBytes.
std::optional<std::string> exceeded_yaml_bytes(std::size_t bytes, const std::string& what);

/// The values of a built tree, counted as exceeded_yaml_bound() counts those of a text (a node
/// reached twice counts twice). The tree must have no cycle.
std::size_t count_yaml_values(const YAML::Node& node);

}  // namespace hpcontact::io

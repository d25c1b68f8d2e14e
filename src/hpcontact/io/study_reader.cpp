// Study files: validated into a flat list of runs (label, case, overrides, published values).
#include "hpcontact/io/study_reader.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <filesystem>
#include <set>

#include "hpcontact/core/error.hpp"
#include "hpcontact/io/problem_reader.hpp"
#include "hpcontact/io/yaml_source.hpp"

namespace hpcontact::io {

namespace {

class StudyBuilder {
 public:
  explicit StudyBuilder(const std::string& file) : source_(file) {
    folder_ = std::filesystem::path(file).parent_path();
  }

  StudySpec build(const YAML::Node& root) {
    StudySpec s;
    s.file = source_.file();
    allow(root, "", {"study", "title", "case", "set", "sweep", "zip", "runs", "columns"});
    s.name = name(root["study"], "study");
    s.title = text(root["title"], "title", false);
    const std::string common_case = root["case"] ? case_path(root["case"], "case") : "";
    const std::vector<std::string> common_sets = strings(root["set"], "set");
    if (root["sweep"] || root["zip"]) add_sweep(root["sweep"], root["zip"], common_case, common_sets, s);
    if (const YAML::Node runs = root["runs"]) {
      require(runs.IsSequence(), runs, "runs", "must be a list of runs");
      for (std::size_t i = 0; i < runs.size(); ++i) {
        const std::string path = join_index("runs", i);
        const YAML::Node r = runs[i];
        require(r.IsMap(), r, path, "must be a map with label, case, set, seed");
        allow(r, path, {"label", "case", "set", "seed"});
        StudyRun run;
        run.label = name(r["label"], path + ".label");
        if (r["case"]) run.case_file = case_path(r["case"], path + ".case");
        else run.case_file = common_case;
        require(!run.case_file.empty(), r, path, "needs a case (or a case for the whole study)");
        run.sets = common_sets;
        for (const auto& set : strings(r["set"], path + ".set")) run.sets.push_back(set);
        if (const YAML::Node seed = r["seed"]) {
          require(seed.IsMap(), seed, path + ".seed", "must be a map of name: number");
          for (auto it = seed.begin(); it != seed.end(); ++it) {
            const std::string key = join_key(path + ".seed", it->first.Scalar());
            const auto v = to_number(it->second);
            require(v.has_value(), it->second, key,
                    "must be a number (got " + quoted_value(it->second) + ")");
            run.seed.emplace_back(it->first.Scalar(), *v);
          }
        }
        s.runs.push_back(std::move(run));
      }
    }
    s.columns = strings(root["columns"], "columns");
    require(!s.runs.empty(), root, "", "a study needs runs or a sweep (got neither)");
    std::set<std::string> labels;
    for (std::size_t i = 0; i < s.runs.size(); ++i)
      if (!labels.insert(s.runs[i].label).second)
        throw InputError(source_.file() + ": run label '" + s.runs[i].label +
                         "' is used twice (labels name the runs' folders and rows)");
    return s;
  }

 private:
  void require(bool ok, const YAML::Node& node, const std::string& path, const std::string& what) {
    if (!ok) source_.fail(node, path.empty() ? "(top level)" : path, what);
  }

  void allow(const YAML::Node& map, const std::string& path, std::set<std::string> keys) {
    for (auto it = map.begin(); it != map.end(); ++it) {
      const std::string key = it->first.Scalar();
      if (keys.count(key)) continue;
      std::string expected;
      for (const auto& k : keys) expected += (expected.empty() ? "" : ", ") + k;
      source_.fail(it->first, join_key(path, key), "unknown key (expected one of: " + expected + ")");
    }
  }

  std::string text(const YAML::Node& node, const std::string& path, bool required) {
    if (!node) {
      require(!required, node, path, "missing required key");
      return "";
    }
    require(node.IsScalar() && !node.Scalar().empty(), node, path,
            "must be a non-empty string (got " + shown_value(node) + ")");
    return node.Scalar();
  }

  /// A name (the study's, a run's label): a non-empty string without control characters, which
  /// it carries into folders, tables, the terminal and a Slurm job's script (where a newline
  /// would end a line and make the rest a command).
  std::string name(const YAML::Node& node, const std::string& path) {
    const std::string value = text(node, path, true);
    require(std::none_of(value.begin(), value.end(), control), node, path,
            "must not hold a control character such as a newline (got " + quoted_value(node) +
                "): it names the study's rows, folders and Slurm job");
    return value;
  }

  static bool control(char c) {
    const auto u = static_cast<unsigned char>(c);
    return u < 0x20 || u == 0x7f;
  }

  std::vector<std::string> strings(const YAML::Node& node, const std::string& path) {
    std::vector<std::string> out;
    if (!node) return out;
    require(node.IsSequence(), node, path, "must be a list of strings (got " + shown_value(node) + ")");
    for (std::size_t i = 0; i < node.size(); ++i) out.push_back(text(node[i], join_index(path, i), true));
    return out;
  }

  /// A case path relative to the study file's folder; it must exist.
  std::string case_path(const YAML::Node& node, const std::string& path) {
    const std::filesystem::path p = folder_ / text(node, path, true);
    std::error_code ec;
    require(std::filesystem::is_regular_file(p, ec), node, path,
            "no such problem file (got '" + p.string() + "')");
    return p.string();
  }

  /// The value as --set takes it: a scalar as written, a list in flow style.
  static std::string value_text(const YAML::Node& v) {
    if (v.IsScalar()) return v.Scalar();
    YAML::Emitter e;
    e << YAML::Flow << v;
    return e.c_str();
  }

  /// One axis of a sweep: keys that vary together, and their values, row by row.
  struct Axis {
    std::vector<std::string> keys;
    std::vector<std::vector<std::string>> rows;  ///< rows[i][k]: the value of keys[k] in row i
  };

  /// The values of `key: [v0, v1, ...]` as --set takes them.
  std::vector<std::string> axis_values(const YAML::Node& list, const std::string& path) {
    require(list.IsSequence() && list.size() > 0, list, path,
            "must be a non-empty list of values (got " + shown_value(list) + ")");
    std::vector<std::string> values;
    for (std::size_t i = 0; i < list.size(); ++i) {
      values.push_back(value_text(list[i]));
      require(std::none_of(values.back().begin(), values.back().end(), control), list[i],
              join_index(path, i),
              "must not hold a control character such as a newline (got " + quoted_value(list[i]) +
                  "): the value names its run (the label of its row and folder)");
    }
    return values;
  }

  /// `sweep`: every key its own axis. `zip`: one axis whose keys vary together, lists of one length.
  std::vector<Axis> sweep_axes(const YAML::Node& sweep, const YAML::Node& zip) {
    std::vector<Axis> axes;
    if (sweep) {
      require(sweep.IsMap() && sweep.size() > 0, sweep, "sweep", "must be a map key.path: [values]");
      for (auto it = sweep.begin(); it != sweep.end(); ++it) {
        const std::string key = it->first.Scalar();
        Axis axis{{key}, {}};
        for (auto& v : axis_values(it->second, join_key("sweep", key))) axis.rows.push_back({v});
        axes.push_back(std::move(axis));
      }
    }
    if (zip) {
      require(zip.IsMap() && zip.size() > 0, zip, "zip",
              "must be a map key.path: [values] (the keys vary together)");
      Axis axis;
      std::string first;
      for (auto it = zip.begin(); it != zip.end(); ++it) {
        const std::string key = it->first.Scalar();
        const std::string path = join_key("zip", key);
        const auto values = axis_values(it->second, path);
        const bool in_sweep =
            std::any_of(axes.begin(), axes.end(), [&](const Axis& a) { return a.keys.front() == key; });
        require(!in_sweep, it->first, path, "is in sweep too: a key varies in one place only");
        if (axis.keys.empty()) {
          first = path;
          axis.rows.resize(values.size());
        }
        require(values.size() == axis.rows.size(), it->second, path,
                "must have as many values as " + first + " (" + std::to_string(axis.rows.size()) +
                    "; got " + std::to_string(values.size()) + "): the keys of zip vary together");
        axis.keys.push_back(key);
        for (std::size_t i = 0; i < values.size(); ++i) axis.rows[i].push_back(values[i]);
      }
      axes.push_back(std::move(axis));
    }
    return axes;
  }

  /// In a run's label each key is named by its last part ("degree=4"), or in full where two
  /// keys of the sweep end alike.
  static std::vector<std::string> label_names(const std::vector<Axis>& axes) {
    std::vector<std::string> keys, names;
    for (const auto& axis : axes) keys.insert(keys.end(), axis.keys.begin(), axis.keys.end());
    auto last_part = [](const std::string& key) {
      const std::size_t dot = key.find_last_of('.');
      return dot == std::string::npos ? key : key.substr(dot + 1);
    };
    for (const auto& key : keys) {
      const auto same = std::count_if(keys.begin(), keys.end(),
                                      [&](const std::string& k) { return last_part(k) == last_part(key); });
      names.push_back(same > 1 ? key : last_part(key));
    }
    return names;
  }

  void add_sweep(const YAML::Node& sweep, const YAML::Node& zip, const std::string& case_file,
                 const std::vector<std::string>& common_sets, StudySpec& s) {
    const YAML::Node where = sweep ? sweep : zip;
    const std::string what = sweep ? "sweep" : "zip";
    require(!case_file.empty(), where, what, "needs the study's case");
    const std::vector<Axis> axes = sweep_axes(sweep, zip);
    const std::vector<std::string> names = label_names(axes);
    std::size_t combinations = 1;
    for (const auto& axis : axes) {
      combinations *= axis.rows.size();
      require(combinations <= 10000, where, what, "more than 10000 combinations");
    }
    for (std::size_t c = 0; c < combinations; ++c) {
      StudyRun run;
      run.case_file = case_file;
      run.sets = common_sets;
      std::vector<std::size_t> row(axes.size());  // the last axis varies fastest
      std::size_t rest = c;
      for (std::size_t a = axes.size(); a-- > 0;) {
        row[a] = rest % axes[a].rows.size();
        rest /= axes[a].rows.size();
      }
      std::size_t name = 0;
      for (std::size_t a = 0; a < axes.size(); ++a)
        for (std::size_t k = 0; k < axes[a].keys.size(); ++k, ++name) {
          const std::string& v = axes[a].rows[row[a]][k];
          run.label += (run.label.empty() ? "" : ", ") + names[name] + "=" + v;
          run.sets.push_back(axes[a].keys[k] + "=" + v);
        }
      s.runs.push_back(std::move(run));
    }
  }

  YamlSource source_;
  std::filesystem::path folder_;
};

}  // namespace

StudySpec parse_study(const std::string& text, const std::string& file_label) {
  const YAML::Node root =
      load_yaml_map(text, file_label, "study file", "a YAML map (study:, runs: or sweep:, ...)");
  try {
    return StudyBuilder(file_label).build(root);
  } catch (const YAML::Exception& e) {
    throw InputError(file_label + ": " + one_line(e.what(), 200));
  }
}

StudySpec read_study(const std::string& path) { return parse_study(read_input_file(path), path); }

}  // namespace hpcontact::io

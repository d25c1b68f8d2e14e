// One run of a 3D problem (ProblemSpec::solid): discretise, solve, post-process, write.
#pragma once

#include <string>

#include "hpcontact/driver/run.hpp"

namespace hpcontact::driver {

/// The 3D part of run_problem(): with an output folder already opened (`folder`, may be null)
/// and its staging folder `stage` (empty: write nothing), writes summary.json, solution.vtu and
/// input.yaml there and commits the folder when everything has been written. Errors propagate
/// as exceptions and leave the folder as it was.
RunResult run_solid(const model::ProblemSpec& spec, const RunOptions& options,
                    OutputFolder* folder, const std::string& stage);

}  // namespace hpcontact::driver

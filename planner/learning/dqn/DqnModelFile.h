// The trained-model file: a text header line ("FLOORCOVER-DQN <version>"), one JSON line of
// metadata (hyper-parameters, environment options, the fingerprint of the corner graph the
// model was trained on, training counters) and two length-prefixed binary sections: the
// online network's weights and Adam's state. A model refuses any other graph.
#pragma once

#include "learning/CoverageEnvironment.h"
#include "learning/torch/DqnAgent.h"
#include "solvers/Solver.h"

#include <cstdint>
#include <iosfwd>
#include <memory>
#include <string>

namespace fc {

// Version 2 adds the state kind ("state": image|graph) and the network ("network": conv|graph);
// version-1 files (image state, CNN) still load.
constexpr int kDqnModelFormatVersion = 2;

struct DqnModelInfo {
    int formatVersion = kDqnModelFormatVersion;
    std::string setting; // "paper", "improved", "graph" or "custom"
    DqnHyperParameters agent;
    EnvironmentOptions environment;
    int nStep = 1;
    OrderRefinement refinement = OrderRefinement::None; // applied by the dqn solver
    // A generalist (graph network only) was trained on many generated floors and fits every
    // corner graph: no fingerprint is checked; nodeCount and cellCount are then those of its
    // largest training floor, the sweep angle is not imposed, and `provenance` says how to
    // make it again.
    bool generalist = false;
    std::string provenance;
    // The graph: its fingerprint decides; the rest makes error messages useful.
    std::uint64_t graphFingerprint = 0;
    int nodeCount = 0;
    int cellCount = 0;
    double stripeAngleDeg = 90.0;
    double coverageWidth = 0.0;
    // Training so far.
    long episodes = 0;
    long steps = 0;
    long trainSteps = 0;
    double trainingSeconds = 0.0;
};

// FNV-1a over the graph's structure: node cells and positions (mm), edges (ends, kind, cell,
// length in mm) and cells (kind, room, reachability).
std::uint64_t graphFingerprint(const CornerGraph& graph);

struct DqnModel {
    DqnModelInfo info;
    std::unique_ptr<DqnAgent> agent;
};

// `source` names the file in error messages. Reading throws InputError for a foreign,
// truncated, corrupt or newer file.
void writeDqnModel(std::ostream& out, const DqnModelInfo& info, const DqnAgent& agent);
DqnModel readDqnModel(std::istream& in, const std::string& source);
DqnModelInfo readDqnModelInfo(std::istream& in, const std::string& source); // header only
// Atomic save; load throws InputError (also for a missing or unreadable file).
void saveDqnModelFile(const std::string& path, const DqnModelInfo& info, const DqnAgent& agent);
DqnModel loadDqnModelFile(const std::string& path);
DqnModelInfo loadDqnModelInfo(const std::string& path);

// Throws InputError ("... was trained for another floor plan ...") unless the model was
// trained on this graph or is a generalist.
void checkModelFitsGraph(const DqnModelInfo& info, const CornerGraph& graph,
                         const std::string& source);

std::string refinementName(OrderRefinement refinement);
OrderRefinement refinementFromName(const std::string& name); // throws InputError

} // namespace fc

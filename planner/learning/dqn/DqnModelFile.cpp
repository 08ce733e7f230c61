#include "learning/dqn/DqnModelFile.h"

#include "formats/FileIO.h"
#include "learning/GraphState.h"
#include "model/Plan.h"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace fc {
namespace {

constexpr const char* kMagic = "FLOORCOVER-DQN";

class Fnv1a {
public:
    void add(std::int64_t value) {
        for (int i = 0; i < 8; ++i) {
            hash_ ^= static_cast<std::uint64_t>(value >> (8 * i)) & 0xffU;
            hash_ *= 1099511628211ULL;
        }
    }
    void addMillimetres(double metres) { add(std::llround(metres * 1000.0)); }
    std::uint64_t value() const { return hash_; }

private:
    std::uint64_t hash_ = 1469598103934665603ULL;
};

nlohmann::json toJson(const DqnModelInfo& m) {
    const DqnHyperParameters& a = m.agent;
    const EnvironmentOptions& e = m.environment;
    return {{"format_version", m.formatVersion},
            {"setting", m.setting},
            {"graph",
             {{"fingerprint", std::to_string(m.graphFingerprint)},
              {"generalist", m.generalist},
              {"nodes", m.nodeCount},
              {"cells", m.cellCount},
              {"sweep_angle_deg", m.stripeAngleDeg},
              {"coverage_width", m.coverageWidth}}},
            {"agent",
             {{"network", a.network == QNetworkKind::Graph ? "graph" : "conv"},
              {"input_channels", a.inputChannels},
              {"conv_channels", {a.conv1Channels, a.conv2Channels, a.conv3Channels}},
              {"hidden_units", a.hiddenUnits},
              {"message_rounds", a.messageRounds},
              {"message_neighbours", a.messageNeighbours},
              {"learning_rate", a.learningRate},
              {"gamma", a.gamma},
              {"batch_size", a.batchSize},
              {"replay_capacity", a.replayCapacity},
              {"huber_delta", a.huberDelta},
              {"gradient_clip_norm", a.gradientClipNorm},
              {"epsilon", {a.epsilonStart, a.epsilonEnd, a.epsilonDecaySteps}},
              {"target_sync_interval", a.targetSyncInterval},
              {"learning_starts", a.learningStarts},
              {"train_interval", a.trainInterval},
              {"seed", std::to_string(a.seed)},
              {"mask_actions", a.maskActions},
              {"mask_target_argmax", a.maskTargetArgmax}}},
            {"environment",
             {{"final_reward", e.finalReward},
              {"double_coverage_reward", e.doubleCoverageReward},
              {"primary_cell_reward", e.primaryCellReward},
              {"transition_cell_reward", e.transitionCellReward},
              {"cost_scale", e.costScale},
              {"coverage_overlap_scale", e.coverageOverlapScale},
              {"max_steps", e.maxSteps},
              {"reward_is_negative_graph_cost", e.rewardIsNegativeGraphCost},
              {"cost_channels", e.costChannels},
              {"state", e.graphState ? "graph" : "image"},
              {"graph_features", e.graphState ? e.graphFeatures : 0}}},
            {"provenance", m.provenance},
            {"n_step", m.nStep},
            {"refinement", refinementName(m.refinement)},
            {"training",
             {{"episodes", m.episodes},
              {"steps", m.steps},
              {"train_steps", m.trainSteps},
              {"seconds", m.trainingSeconds}}}};
}

DqnModelInfo fromJson(const nlohmann::json& j) {
    DqnModelInfo m;
    m.formatVersion = j.at("format_version").get<int>();
    m.setting = j.at("setting").get<std::string>();
    const auto& g = j.at("graph");
    m.graphFingerprint = std::stoull(g.at("fingerprint").get<std::string>());
    m.generalist = g.value("generalist", false);
    m.provenance = j.value("provenance", std::string());
    m.nodeCount = g.at("nodes").get<int>();
    m.cellCount = g.at("cells").get<int>();
    m.stripeAngleDeg = g.at("sweep_angle_deg").get<double>();
    m.coverageWidth = g.at("coverage_width").get<double>();
    const auto& a = j.at("agent");
    DqnHyperParameters& p = m.agent;
    const auto conv = a.at("conv_channels").get<std::vector<int>>();
    if (conv.size() != 3)
        throw std::invalid_argument("conv_channels needs three entries");
    p.inputChannels = a.value("input_channels", 3);
    const std::string network = a.value("network", std::string("conv"));
    if (network != "conv" && network != "graph")
        throw std::invalid_argument("unknown network \"" + network + "\" (conv, graph)");
    p.network = network == "graph" ? QNetworkKind::Graph : QNetworkKind::Convolutional;
    p.conv1Channels = conv[0];
    p.conv2Channels = conv[1];
    p.conv3Channels = conv[2];
    p.hiddenUnits = a.at("hidden_units").get<int>();
    p.messageRounds = a.value("message_rounds", 0); // absent in files of the first networks
    p.messageNeighbours = a.value("message_neighbours", 12);
    p.learningRate = a.at("learning_rate").get<double>();
    p.gamma = a.at("gamma").get<double>();
    p.batchSize = a.at("batch_size").get<int>();
    p.replayCapacity = a.at("replay_capacity").get<int>();
    p.huberDelta = a.at("huber_delta").get<double>();
    p.gradientClipNorm = a.at("gradient_clip_norm").get<double>();
    const auto& eps = a.at("epsilon");
    p.epsilonStart = eps.at(0).get<double>();
    p.epsilonEnd = eps.at(1).get<double>();
    p.epsilonDecaySteps = eps.at(2).get<long>();
    p.targetSyncInterval = a.at("target_sync_interval").get<int>();
    p.learningStarts = a.at("learning_starts").get<int>();
    p.trainInterval = a.at("train_interval").get<int>();
    p.seed = std::stoull(a.at("seed").get<std::string>());
    p.maskActions = a.at("mask_actions").get<bool>();
    p.maskTargetArgmax = a.at("mask_target_argmax").get<bool>();
    const auto& e = j.at("environment");
    EnvironmentOptions& o = m.environment;
    o.finalReward = e.at("final_reward").get<double>();
    o.doubleCoverageReward = e.at("double_coverage_reward").get<double>();
    o.primaryCellReward = e.at("primary_cell_reward").get<double>();
    o.transitionCellReward = e.at("transition_cell_reward").get<double>();
    o.costScale = e.at("cost_scale").get<double>();
    o.coverageOverlapScale = e.at("coverage_overlap_scale").get<double>();
    o.maxSteps = e.at("max_steps").get<int>();
    o.rewardIsNegativeGraphCost = e.at("reward_is_negative_graph_cost").get<bool>();
    o.costChannels = e.value("cost_channels", false);
    const std::string state = e.value("state", std::string("image"));
    if (state != "image" && state != "graph")
        throw std::invalid_argument("unknown state kind \"" + state + "\" (image, graph)");
    o.graphState = state == "graph";
    if (o.graphState != (p.network == QNetworkKind::Graph))
        throw std::invalid_argument("a " + state + " state needs the " +
                                    (o.graphState ? "graph" : "conv") + " network, not " + network);
    if (o.graphState) {
        // Version-2 files of the first graph state have 14 features per corner.
        o.graphFeatures = e.value("graph_features", p.inputChannels);
        if ((o.graphFeatures != kGraphFeatureCount && o.graphFeatures != kFirstGraphFeatureCount) ||
            o.graphFeatures != p.inputChannels)
            throw std::invalid_argument(
                "a graph state of " + std::to_string(p.inputChannels) +
                " features per corner, which this version does not know (it reads " +
                std::to_string(kFirstGraphFeatureCount) + " or " +
                std::to_string(kGraphFeatureCount) + ")");
    }
    m.nStep = j.at("n_step").get<int>();
    m.refinement = refinementFromName(j.at("refinement").get<std::string>());
    const auto& t = j.at("training");
    m.episodes = t.at("episodes").get<long>();
    m.steps = t.at("steps").get<long>();
    m.trainSteps = t.at("train_steps").get<long>();
    m.trainingSeconds = t.at("seconds").get<double>();
    if (m.nodeCount <= 0 || m.cellCount <= 0 || m.nStep < 1 || p.conv1Channels <= 0 ||
        p.conv2Channels <= 0 || p.conv3Channels <= 0 || p.hiddenUnits <= 0 || p.messageRounds < 0 ||
        p.messageRounds > 8 || p.messageNeighbours < 1 || p.messageNeighbours > 64 ||
        p.inputChannels != CoverageEnvironment::channelCountFor(o) || m.episodes < 0 ||
        m.steps < 0 || m.trainSteps < 0)
        throw std::invalid_argument("sizes and counts out of range");
    if (m.generalist && p.network != QNetworkKind::Graph)
        throw std::invalid_argument("only a graph network can be a generalist");
    return m;
}

void writeSection(std::ostream& out, const char* name, const std::string& bytes) {
    out << name << ' ' << bytes.size() << '\n';
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

std::string readSection(std::istream& in, const char* name, const std::string& source) {
    std::string line;
    if (!std::getline(in, line))
        throw InputError(source + ": truncated model file (no " + name + " section)");
    std::istringstream header(line);
    std::string tag;
    long long size = -1;
    header >> tag >> size;
    if (tag != name || size < 0 || size > (1LL << 32))
        throw InputError(source + ": corrupt model file (bad " + name + " section header)");
    std::string bytes(static_cast<std::size_t>(size), '\0');
    in.read(bytes.data(), static_cast<std::streamsize>(size));
    if (in.gcount() != size)
        throw InputError(source + ": truncated model file (" + name + " section cut short)");
    return bytes;
}

DqnModelInfo readInfo(std::istream& in, const std::string& source) {
    std::string line;
    if (!std::getline(in, line) || line.rfind(kMagic, 0) != 0)
        throw InputError(source + ": not a FloorCover DQN model (missing the " +
                         std::string(kMagic) + " header)");
    int version = 0;
    try {
        version = std::stoi(line.substr(std::string(kMagic).size()));
    } catch (const std::exception&) {
        throw InputError(source + ": corrupt model file (bad format version)");
    }
    if (version > kDqnModelFormatVersion || version < 1)
        throw InputError(source + ": model format version " + std::to_string(version) +
                         " is not supported (this build reads up to version " +
                         std::to_string(kDqnModelFormatVersion) + ")");
    if (!std::getline(in, line))
        throw InputError(source + ": truncated model file (no metadata)");
    try {
        return fromJson(nlohmann::json::parse(line));
    } catch (const std::exception& e) {
        throw InputError(source + ": corrupt model metadata: " + e.what());
    }
}

} // namespace

std::uint64_t graphFingerprint(const CornerGraph& graph) {
    Fnv1a h;
    h.add(static_cast<std::int64_t>(graph.nodes.size()));
    for (const GraphNode& n : graph.nodes) {
        h.add(n.cell);
        h.add(static_cast<int>(n.corner));
        h.addMillimetres(n.position.x);
        h.addMillimetres(n.position.y);
    }
    h.add(static_cast<std::int64_t>(graph.edges.size()));
    for (const GraphEdge& e : graph.edges) {
        h.add(e.u);
        h.add(e.v);
        h.add(static_cast<int>(e.kind));
        h.add(e.cell);
        h.add(e.parallel ? 1 : 0);
        h.addMillimetres(e.length);
    }
    h.add(static_cast<std::int64_t>(graph.cells.size()));
    for (const GraphCell& c : graph.cells) {
        h.add(static_cast<int>(c.kind));
        h.add(c.room);
        h.add(c.reachable ? 1 : 0);
    }
    return h.value();
}

void writeDqnModel(std::ostream& out, const DqnModelInfo& info, const DqnAgent& agent) {
    out << kMagic << ' ' << kDqnModelFormatVersion << '\n' << toJson(info).dump() << '\n';
    std::ostringstream weights;
    agent.saveWeights(weights);
    writeSection(out, "weights", weights.str());
    std::ostringstream optimizer;
    agent.saveOptimizer(optimizer);
    writeSection(out, "optimizer", optimizer.str());
    out << "end\n";
}

DqnModelInfo readDqnModelInfo(std::istream& in, const std::string& source) {
    return readInfo(in, source);
}

DqnModel readDqnModel(std::istream& in, const std::string& source) {
    DqnModel model;
    model.info = readInfo(in, source);
    const int size = static_cast<int>(std::ceil(std::sqrt(double(model.info.nodeCount)) - 1e-9));
    const std::string weights = readSection(in, "weights", source);
    const std::string optimizer = readSection(in, "optimizer", source);
    std::string end;
    if (!std::getline(in, end) || end != "end")
        throw InputError(source + ": truncated model file (no end marker)");
    try {
        model.agent = std::make_unique<DqnAgent>(size, model.info.nodeCount, model.info.agent);
        std::istringstream w(weights);
        model.agent->loadWeights(w);
        std::istringstream o(optimizer);
        model.agent->loadOptimizer(o);
        model.agent->restoreCounters(model.info.steps, model.info.trainSteps);
    } catch (const std::exception& e) {
        throw InputError(source + ": corrupt model weights: " + e.what());
    }
    return model;
}

void saveDqnModelFile(const std::string& path, const DqnModelInfo& info, const DqnAgent& agent) {
    std::ostringstream out;
    writeDqnModel(out, info, agent);
    writeFileAtomically(path, out.str());
}

namespace {
std::ifstream openModel(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw InputError(path + ": cannot open the model file");
    return in;
}
} // namespace

DqnModel loadDqnModelFile(const std::string& path) {
    std::ifstream in = openModel(path);
    return readDqnModel(in, path);
}

DqnModelInfo loadDqnModelInfo(const std::string& path) {
    std::ifstream in = openModel(path);
    return readInfo(in, path);
}

void checkModelFitsGraph(const DqnModelInfo& info, const CornerGraph& graph,
                         const std::string& source) {
    if (info.generalist || info.graphFingerprint == graphFingerprint(graph))
        return;
    std::ostringstream msg;
    msg << source << ": the model was trained for another floor plan or robot profile (it knows "
        << info.nodeCount << " corners in " << info.cellCount << " cells at sweep angle "
        << info.stripeAngleDeg << " deg and coverage width " << info.coverageWidth
        << " m; this plan has " << graph.nodes.size() << " corners in " << graph.cells.size()
        << " cells); train a model for this plan";
    throw InputError(msg.str());
}

std::string refinementName(OrderRefinement refinement) {
    switch (refinement) {
    case OrderRefinement::None:
        return "none";
    case OrderRefinement::Corners:
        return "corners";
    case OrderRefinement::LocalSearch:
        return "local-search";
    }
    return "none";
}

OrderRefinement refinementFromName(const std::string& name) {
    if (name == "none")
        return OrderRefinement::None;
    if (name == "corners")
        return OrderRefinement::Corners;
    if (name == "local-search")
        return OrderRefinement::LocalSearch;
    throw InputError("unknown refinement \"" + name + "\" (none, corners, local-search)");
}

} // namespace fc

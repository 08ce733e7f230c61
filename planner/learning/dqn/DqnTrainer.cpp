#include "learning/dqn/DqnTrainer.h"

#include "model/Plan.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace fc {
namespace {

using Clock = std::chrono::steady_clock;

// Up to this many required cells the evaluation's reference is the exact optimum.
constexpr int kExactReferenceCells = 12;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

} // namespace

TrainingOptions TrainingOptions::paper(std::uint64_t seed) {
    TrainingOptions o;
    o.setting = "paper";
    o.agent.seed = seed;
    o.agent.maskActions = false;
    o.agent.maskTargetArgmax = false;
    return o;
}

TrainingOptions TrainingOptions::improved(std::uint64_t seed) {
    TrainingOptions o;
    o.setting = "improved";
    DqnHyperParameters& a = o.agent;
    a.seed = seed;
    a.maskActions = true;
    a.maskTargetArgmax = true;
    // A narrower network: on a 16 x 16 image (office) the paper's costs 120 ms per update on
    // one core, this one about 30 ms.
    a.conv1Channels = 16;
    a.conv2Channels = 32;
    a.conv3Channels = 32;
    a.hiddenUnits = 128;
    a.learningRate = 1e-3;
    a.epsilonDecaySteps = 8'000;
    a.targetSyncInterval = 500;
    a.replayCapacity = 20'000;
    a.gradientClipNorm = 10.0;
    // With masking every episode reaches the goal, so the final reward carries no
    // information; the return is minus the walk's graph cost (in units of the longest edge).
    o.environment.rewardIsNegativeGraphCost = true;
    o.environment.finalReward = 0.0;
    o.environment.costScale = 1.0;
    o.environment.costChannels = true;
    // n-step returns (nStep > 1) learnt slower here: with epsilon-greedy behaviour the
    // uncorrected n-step target is biased (docs/dqn.md, ablation).
    o.nStep = 1;
    o.refinement = OrderRefinement::LocalSearch;
    return o;
}

TrainingOptions TrainingOptions::graph(std::uint64_t seed) {
    TrainingOptions o = improved(seed);
    o.setting = "graph";
    o.environment.costChannels = false;
    o.environment.graphState = true;
    DqnHyperParameters& a = o.agent;
    a.network = QNetworkKind::Graph;
    // 32 units: a gradient step on office (232 corners) costs about 11 ms on one core, 64
    // units about 26 ms, for no better policy in a 60 s trial.
    a.hiddenUnits = 32;
    // A graph state is actionCount x 14 floats (13 kB on office's 232 corners) per side of a
    // transition.
    a.replayCapacity = 10'000;
    a.epsilonDecaySteps = 10'000;
    return o;
}

TrainingOptions TrainingOptions::named(const std::string& setting, std::uint64_t seed) {
    if (setting == "paper")
        return paper(seed);
    if (setting == "improved")
        return improved(seed);
    if (setting == "graph")
        return graph(seed);
    throw InputError("unknown training setting \"" + setting + "\" (paper, improved, graph)");
}

DqnTrainer::DqnTrainer(const CornerGraph& graph, TrainingOptions options, double stripeAngleDeg,
                       double coverageWidth)
    : options_(std::move(options)), stripeAngleDeg_(stripeAngleDeg), coverageWidth_(coverageWidth),
      rng_(options_.agent.seed) {
    if (options_.nStep < 1)
        throw std::invalid_argument("DqnTrainer: n-step must be at least 1");
    if (options_.environment.graphState != (options_.agent.network == QNetworkKind::Graph))
        throw std::invalid_argument(
            "DqnTrainer: the graph state needs the graph network and the image the CNN");
    // Fine-tuning: the state and network are the initial model's, so they are settled
    // before the environment is built on them; the schedule is this run's.
    const std::shared_ptr<const DqnModel> initial = options_.initialModel;
    if (initial) {
        const DqnModelInfo& from = initial->info;
        if (from.agent.network != QNetworkKind::Graph || !options_.environment.graphState ||
            from.environment.graphFeatures != options_.environment.graphFeatures)
            throw InputError("fine-tuning needs a graph-setting model with the same features");
        options_.agent.hiddenUnits = from.agent.hiddenUnits;
        options_.agent.messageRounds = from.agent.messageRounds;
        options_.agent.messageNeighbours = from.agent.messageNeighbours;
        options_.agent.epsilonStart =
            std::min(options_.agent.epsilonStart, options_.fineTuneEpsilon);
        options_.environment = from.environment;
        options_.refinement = from.refinement;
        initialProvenance_ = from.generalist ? "fine-tuned from the generalist model (" +
                                                   std::to_string(from.episodes) + " episodes)"
                                             : "fine-tuned from a model of this plan";
    }
    floors_.push_back(std::make_unique<CornerGraph>(graph));
    environments_.push_back(
        std::make_unique<CoverageEnvironment>(*floors_.front(), options_.environment));
    useFloor(0);
    options_.agent.inputChannels = environment_->channelCount();
    agent_ = std::make_unique<DqnAgent>(environment_->size(), environment_->actionCount(),
                                        options_.agent);
    if (initial) {
        std::stringstream weights;
        initial->agent->saveWeights(weights);
        agent_->loadWeights(weights);
    }
    options_.initialModel.reset(); // the weights are copied; do not keep the model alive
}

DqnTrainer::DqnTrainer(std::vector<CornerGraph> floors, TrainingOptions options,
                       double coverageWidth, std::string provenance)
    : generalist_(true), provenance_(std::move(provenance)), options_(std::move(options)),
      stripeAngleDeg_(0.0), coverageWidth_(coverageWidth), rng_(options_.agent.seed) {
    if (floors.empty())
        throw std::invalid_argument("DqnTrainer: a generalist needs at least one floor");
    if (!options_.environment.graphState || options_.agent.network != QNetworkKind::Graph)
        throw std::invalid_argument("DqnTrainer: only the graph setting trains a generalist");
    if (options_.nStep < 1)
        throw std::invalid_argument("DqnTrainer: n-step must be at least 1");
    std::size_t largest = 0;
    for (CornerGraph& floor : floors) {
        floors_.push_back(std::make_unique<CornerGraph>(std::move(floor)));
        environments_.push_back(
            std::make_unique<CoverageEnvironment>(*floors_.back(), options_.environment));
        if (floors_.back()->nodes.size() > floors_[largest]->nodes.size())
            largest = floors_.size() - 1;
    }
    useFloor(largest);
    options_.agent.inputChannels = environment_->channelCount();
    agent_ = std::make_unique<DqnAgent>(environment_->size(), environment_->actionCount(),
                                        options_.agent);
}

DqnTrainer::DqnTrainer(const CornerGraph& graph, DqnModel model, const std::string& source) {
    checkModelFitsGraph(model.info, graph, source);
    const DqnModelInfo& info = model.info;
    generalist_ = info.generalist;
    provenance_ = info.provenance;
    options_.setting = info.setting;
    options_.agent = info.agent;
    options_.environment = info.environment;
    options_.nStep = info.nStep;
    options_.refinement = info.refinement;
    stripeAngleDeg_ = info.stripeAngleDeg;
    coverageWidth_ = info.coverageWidth;
    episodes_ = info.episodes;
    seconds_ = info.trainingSeconds;
    // A different stream than the first run's, still a function of the seed and progress.
    rng_.seed(info.agent.seed + static_cast<std::uint64_t>(info.episodes) * 7919U);
    floors_.push_back(std::make_unique<CornerGraph>(graph));
    environments_.push_back(
        std::make_unique<CoverageEnvironment>(*floors_.front(), options_.environment));
    useFloor(0);
    agent_ = std::move(model.agent);
}

void DqnTrainer::useFloor(std::size_t index) {
    graph_ = floors_[index].get();
    environment_ = environments_[index].get();
}

const CornerGraph& DqnTrainer::floorOfQuery(std::size_t query) const {
    return *floors_[evaluationFloors_.empty() ? 0 : evaluationFloors_[query]];
}

DqnTrainer::~DqnTrainer() = default;

void DqnTrainer::flush(std::deque<PendingStep>& pending, const std::vector<float>& next,
                       const std::vector<char>& nextMask, bool done, bool all, double& lossSum,
                       int& lossCount) {
    const double gamma = options_.agent.gamma;
    while (!pending.empty()) {
        double reward = 0.0;
        double discount = 1.0;
        for (const PendingStep& p : pending) {
            reward += discount * p.reward;
            discount *= gamma;
        }
        Transition t;
        t.observation = std::move(pending.front().observation);
        t.action = pending.front().action;
        t.reward = static_cast<float>(reward);
        t.nextObservation = next;
        t.nextMask = nextMask;
        t.done = done;
        t.steps = static_cast<int>(pending.size());
        pending.pop_front();
        const double loss = agent_->observe(std::move(t));
        if (!std::isnan(loss)) {
            lossSum += loss;
            ++lossCount;
        }
        if (!all)
            break;
    }
}

double DqnTrainer::runEpisode(double& lossSum, int& lossCount) {
    if (floors_.size() > 1) {
        std::uniform_int_distribution<std::size_t> pick(0, floors_.size() - 1);
        useFloor(pick(rng_));
    }
    CoverageEnvironment& env = *environment_;
    std::vector<float> observation = env.reset(rng_);
    std::deque<PendingStep> pending;
    double episodeReward = 0.0;
    while (!env.done()) {
        const int action = agent_->act(observation, env.actionMask(), agent_->epsilon(), rng_);
        const StepResult result = env.step(action);
        episodeReward += result.reward;
        pending.push_back({std::move(observation), action, result.reward});
        observation = env.observation();
        const std::vector<char> mask = env.actionMask();
        if (result.done)
            flush(pending, observation, mask, true, true, lossSum, lossCount);
        else if (static_cast<int>(pending.size()) >= options_.nStep)
            flush(pending, observation, mask, false, false, lossSum, lossCount);
    }
    return episodeReward;
}

TrainingStop DqnTrainer::train(long episodes, double seconds,
                               const std::function<void(const TrainingProgress&)>& progress,
                               const std::function<bool()>& cancelled) {
    if (episodes <= 0 && seconds <= 0.0 && !cancelled)
        throw std::invalid_argument("DqnTrainer::train: no episode or time limit");
    const Clock::time_point start = Clock::now();
    const long firstSteps = agent_->stepCount();
    const double earlierSeconds = seconds_;
    long done = 0;
    for (;;) {
        if (cancelled && cancelled())
            return TrainingStop::Cancelled;
        if (episodes > 0 && done >= episodes)
            return TrainingStop::EpisodeLimit;
        if (seconds > 0.0 && secondsSince(start) >= seconds)
            return TrainingStop::TimeLimit;

        double lossSum = 0.0;
        int lossCount = 0;
        TrainingProgress p;
        p.reward = runEpisode(lossSum, lossCount);
        ++episodes_;
        ++done;
        recentRewards_.push_back(p.reward);
        while (static_cast<int>(recentRewards_.size()) > std::max(1, options_.movingAverageWindow))
            recentRewards_.pop_front();
        const double elapsed = secondsSince(start);
        seconds_ = earlierSeconds + elapsed;

        p.episode = episodes_;
        p.movingAverage = std::accumulate(recentRewards_.begin(), recentRewards_.end(), 0.0) /
                          static_cast<double>(recentRewards_.size());
        p.loss = lossCount > 0 ? lossSum / lossCount : std::numeric_limits<double>::quiet_NaN();
        p.epsilon = agent_->epsilon();
        p.totalSteps = agent_->stepCount();
        p.stepsPerSecond =
            elapsed > 0.0 ? static_cast<double>(p.totalSteps - firstSteps) / elapsed : 0.0;
        if (options_.evaluationInterval > 0 && episodes_ % options_.evaluationInterval == 0) {
            p.evaluation = evaluate();
            seconds_ = earlierSeconds + secondsSince(start); // evaluation time counts too
        }
        p.elapsedSeconds = seconds_;
        if (progress)
            progress(p);
    }
}

EvaluationReport DqnTrainer::evaluate(const SolveControl& control) {
    auto throwIfCancelled = [&control] {
        if (control.cancelled && control.cancelled())
            throw SolverError("evaluation cancelled");
    };
    // The solvers below see the cancellation only; the progress counts queries (references
    // first when they are still to compute).
    const SolveControl inner{control.cancelled, {}};
    const std::size_t steps =
        evaluationQueries_.empty()
            ? 2 * static_cast<std::size_t>(std::max(1, options_.evaluationQueries))
            : evaluationQueries_.size();
    std::size_t done = 0;
    auto advance = [&control, &done, steps] {
        if (control.progress)
            control.progress(static_cast<double>(++done) / static_cast<double>(steps));
    };
    if (evaluationQueries_.empty()) {
        // Spread over the floors (a generalist) in turn, each floor's queries from its own
        // seed (one floor: the same queries as before generalists existed).
        const int total = std::max(1, options_.evaluationQueries);
        const auto floorCount = static_cast<int>(floors_.size());
        std::vector<std::vector<Query>> perFloor(floors_.size());
        for (std::size_t f = 0; f < floors_.size(); ++f) {
            const CornerGraph& g = *floors_[f];
            const int count = (total - static_cast<int>(f) + floorCount - 1) / floorCount;
            if (count > 0)
                perFloor[f] =
                    randomQueries(g, count, (options_.agent.seed ^ 0x5eedULL) + f * 104729ULL,
                                  roomCount(g) > 1 ? QuerySet::RoomSubsets : QuerySet::AllCells);
        }
        std::vector<Query> queries;
        std::vector<std::size_t> floorOf;
        for (int i = 0; i < total; ++i) {
            const std::size_t floor = static_cast<std::size_t>(i % floorCount);
            queries.push_back(perFloor[floor][static_cast<std::size_t>(i / floorCount)]);
            floorOf.push_back(floor);
        }
        std::vector<double> costs;
        int exactCount = 0;
        for (std::size_t i = 0; i < queries.size(); ++i) {
            throwIfCancelled();
            const Query& q = queries[i];
            const CornerGraph& g = *floors_[floorOf[i]];
            const int cells = static_cast<int>(std::count(q.required.begin(), q.required.end(), 1));
            const bool exact = cells <= kExactReferenceCells;
            exactCount += exact ? 1 : 0;
            costs.push_back(exact ? solveExact(g, q, {}, inner).graphCost
                                  : solveHeuristic(g, q, inner).graphCost);
            advance();
        }
        evaluationQueries_ = std::move(queries); // only complete references are kept
        evaluationFloors_ = std::move(floorOf);
        referenceCosts_ = std::move(costs);
        referenceName_ = exactCount == static_cast<int>(evaluationQueries_.size()) ? "exact"
                         : exactCount == 0                                         ? "heuristic"
                                           : "exact/heuristic";
    }
    EvaluationReport report;
    report.reference = referenceName_;
    report.queries = static_cast<int>(evaluationQueries_.size());
    int finished = 0;
    for (std::size_t i = 0; i < evaluationQueries_.size(); ++i) {
        throwIfCancelled();
        const Clock::time_point start = Clock::now();
        try {
            const Solution raw =
                solveWithPolicy(*agent_, floorOfQuery(i), evaluationQueries_[i],
                                options_.environment, OrderRefinement::None, inner);
            const Solution refined =
                refineCellOrder(floorOfQuery(i), evaluationQueries_[i], raw, options_.refinement,
                                kPolicyRefinementBudget, inner);
            report.meanMilliseconds += 1000.0 * secondsSince(start);
            const double reference = std::max(referenceCosts_[i], 1e-9);
            const double gap = raw.graphCost / reference - 1.0;
            report.meanGap += gap;
            report.maxGap = std::max(report.maxGap, gap);
            report.meanRefinedGap += refined.graphCost / reference - 1.0;
            ++finished;
        } catch (const SolverError&) {
            throwIfCancelled(); // a cancelled rollout is not a failure of the policy
            ++report.failures;
        }
        advance();
    }
    if (finished > 0) {
        report.meanGap /= finished;
        report.meanRefinedGap /= finished;
        report.meanMilliseconds /= finished;
    }
    if (finished > 0 && report.failures == 0 &&
        (!bestReport_ || report.meanGap < bestReport_->meanGap)) {
        std::ostringstream weights;
        agent_->saveWeights(weights);
        bestWeights_ = weights.str();
        bestReport_ = report;
        bestEpisode_ = episodes_;
    }
    return report;
}

bool DqnTrainer::restoreBestEvaluated() {
    if (bestWeights_.empty() || bestEpisode_ == episodes_)
        return false; // nothing kept, or the current weights are the best
    std::istringstream weights(bestWeights_);
    agent_->loadWeights(weights);
    return true;
}

DqnModelInfo DqnTrainer::modelInfo() const {
    DqnModelInfo info;
    info.setting = options_.setting;
    info.agent = options_.agent;
    info.environment = options_.environment;
    info.nStep = options_.nStep;
    info.refinement = options_.refinement;
    info.generalist = generalist_;
    info.provenance = provenance_.empty() ? initialProvenance_ : provenance_;
    // A generalist records its largest floor (only for messages) and no fingerprint.
    const CornerGraph* shown = graph_;
    for (const auto& floor : floors_)
        if (floor->nodes.size() > shown->nodes.size())
            shown = floor.get();
    info.graphFingerprint = generalist_ ? 0 : graphFingerprint(*graph_);
    info.nodeCount = static_cast<int>(shown->nodes.size());
    info.cellCount = static_cast<int>(shown->cells.size());
    info.stripeAngleDeg = stripeAngleDeg_;
    info.coverageWidth = coverageWidth_;
    info.episodes = episodes_;
    info.steps = agent_->stepCount();
    info.trainSteps = agent_->trainStepCount();
    info.trainingSeconds = seconds_;
    return info;
}

void DqnTrainer::save(const std::string& path) const {
    saveDqnModelFile(path, modelInfo(), *agent_);
}

} // namespace fc

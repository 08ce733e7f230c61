// Training of the Double-DQN planner for one corner graph (SPEC sect. 5): the episode loop,
// n-step transitions, progress reports, cancellation between episodes and resumption, and
// the periodic evaluation on a fixed query set against the exact or heuristic solver.
// Runs on any thread; the caller's callbacks run on the training thread.
#pragma once

#include "learning/CoverageEnvironment.h"
#include "learning/dqn/DqnModelFile.h"
#include "learning/dqn/DqnPolicy.h"
#include "learning/torch/DqnAgent.h"

#include <chrono>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <random>
#include <string>

namespace fc {

struct TrainingOptions {
    std::string setting = "custom"; // recorded in the model file
    DqnHyperParameters agent;
    EnvironmentOptions environment;
    int nStep = 1;                                      // 1 = the paper's one-step target
    OrderRefinement refinement = OrderRefinement::None; // what the dqn solver applies
    int evaluationInterval = 0;                         // episodes; 0 = no evaluation
    int evaluationQueries = 20;
    int movingAverageWindow = 100;
    // Fine-tuning: the weights to start from (a generalist, or any graph model with the same
    // network); exploration then starts at fineTuneEpsilon instead of epsilonStart, so that
    // the first episodes follow the policy that is being refined. Null: from scratch.
    std::shared_ptr<const DqnModel> initialModel;
    double fineTuneEpsilon = 0.3;

    // The paper's setting: its network, optimiser and schedule, no masking, one-step targets,
    // the paper's rewards, the learnt walk as it is.
    static TrainingOptions paper(std::uint64_t seed = 1);
    // Ours: masked acting and argmax, reward = minus the added graph cost, cost channels in
    // the state, a narrower network and a schedule sized for minutes on one core, and the
    // walk's corners and order refined by the true-cost local search at inference.
    static TrainingOptions improved(std::uint64_t seed = 1);
    // improved() with the graph-level state (GraphState.h) and the per-corner network instead
    // of the image and its CNN: cost grows with the corners, not with SIZE^2 x channels.
    static TrainingOptions graph(std::uint64_t seed = 1);
    // "paper", "improved" or "graph"; throws InputError naming the choices otherwise.
    static TrainingOptions named(const std::string& setting, std::uint64_t seed = 1);
};

struct EvaluationReport {
    int queries = 0;
    int failures = 0;     // rollouts that did not finish (never with masking)
    double meanGap = 0.0; // policy alone vs reference, mean of cost / reference - 1
    double maxGap = 0.0;
    double meanRefinedGap = 0.0; // after the model's refinement
    double meanMilliseconds = 0.0;
    std::string reference; // "exact", "heuristic" or a mix
};

struct TrainingProgress {
    long episode = 0;           // episodes so far (including earlier runs)
    double reward = 0.0;        // of the episode just finished
    double movingAverage = 0.0; // over the last movingAverageWindow episodes
    double loss = 0.0;          // mean over the episode's gradient steps; NaN if none
    double epsilon = 0.0;
    double stepsPerSecond = 0.0; // in this run
    long totalSteps = 0;
    double elapsedSeconds = 0.0;                // training time including earlier runs
    std::optional<EvaluationReport> evaluation; // set when this episode was evaluated
};

enum class TrainingStop { EpisodeLimit, TimeLimit, Cancelled };

class DqnTrainer {
public:
    // A new model for `graph`; the graph is copied.
    DqnTrainer(const CornerGraph& graph, TrainingOptions options, double stripeAngleDeg = 90.0,
               double coverageWidth = 1.0);
    // Resumes a saved model (throws InputError when it was trained for another graph). The
    // replay memory is not saved: it refills from the restored policy.
    DqnTrainer(const CornerGraph& graph, DqnModel model, const std::string& source);
    // A generalist: one graph-setting model for every floor of `floors` (each episode draws
    // one; evaluation queries are spread over them). Throws std::invalid_argument for an
    // empty set or the image setting.
    DqnTrainer(std::vector<CornerGraph> floors, TrainingOptions options, double coverageWidth,
               std::string provenance);
    ~DqnTrainer();

    // Trains until `episodes` more episodes (<= 0: no limit) or `seconds` more seconds (<= 0:
    // no limit) have passed or `cancelled` returns true; checked between episodes, so the
    // model is always consistent. Call again to resume. Without any limit and without a
    // cancellation callback it throws std::invalid_argument.
    TrainingStop train(long episodes, double seconds,
                       const std::function<void(const TrainingProgress&)>& progress = {},
                       const std::function<bool()>& cancelled = {});

    // Learning from demonstrations (DQfD): `perFloor` expert walks on every floor, half on
    // the evaluation's kind of query (room subsets or all cells, from another seed) and half
    // on training episodes' random starts, ends and pre-covered sets. Each is solved by the
    // exact solver (up to 12 cells) or the heuristic and replayed into the agent's
    // demonstrations, which then join every batch with a margin loss (DqnHyperParameters).
    // Graph setting only (std::invalid_argument otherwise). Cancellable between walks;
    // returns the transitions added.
    long addDemonstrations(int perFloor, const SolveControl& control = {});
    // `steps` gradient steps on the demonstrations alone (before or between episodes); the
    // target network syncs every targetSyncInterval of them. Returns the mean loss.
    double pretrain(long steps);

    // The fixed query set (all cells, or random room subsets on floors with several rooms).
    // Cancellable (control.cancelled): throws SolverError, and a cancelled first evaluation
    // keeps no partial reference costs.
    EvaluationReport evaluate(const SolveControl& control = {});

    // DQN's policy swings from evaluation to evaluation (on office between 10% and 33% above
    // the reference within two minutes of fine-tuning), so the weights of the best evaluation
    // so far are kept (policy alone, mean gap). This puts them back when the current weights
    // were evaluated worse or not at all since; returns whether it did. The counters stay.
    bool restoreBestEvaluated();
    // The best evaluation so far (none: empty).
    std::optional<EvaluationReport> bestEvaluation() const { return bestReport_; }
    long bestEvaluatedEpisode() const { return bestEpisode_; }

    DqnModelInfo modelInfo() const;
    void save(const std::string& path) const;
    const DqnAgent& agent() const { return *agent_; }
    const CornerGraph& graph() const { return *graph_; }
    bool generalist() const { return generalist_; }
    const TrainingOptions& options() const { return options_; }
    long episodes() const { return episodes_; }

private:
    struct PendingStep {
        std::vector<float> observation;
        int action = 0;
        double reward = 0.0;
    };
    double runEpisode(double& lossSum, int& lossCount);
    void flush(std::deque<PendingStep>& pending, const std::vector<float>& next,
               const std::vector<char>& nextMask, bool done, bool all, double& lossSum,
               int& lossCount);

    void useFloor(std::size_t index);
    const CornerGraph& floorOfQuery(std::size_t query) const;

    // The floors trained on (one unless a generalist); graph_ and environment_ are the
    // current episode's.
    std::vector<std::unique_ptr<CornerGraph>> floors_; // stable addresses
    std::vector<std::unique_ptr<CoverageEnvironment>> environments_;
    CornerGraph* graph_ = nullptr;
    bool generalist_ = false;
    std::string provenance_;
    std::string initialProvenance_; // fine-tuning: where the weights came from
    TrainingOptions options_;
    double stripeAngleDeg_ = 90.0;
    double coverageWidth_ = 1.0;
    CoverageEnvironment* environment_ = nullptr;
    std::unique_ptr<DqnAgent> agent_;
    std::mt19937_64 rng_;
    long episodes_ = 0;
    double seconds_ = 0.0;
    std::deque<double> recentRewards_;
    std::vector<Query> evaluationQueries_;
    std::vector<std::size_t> evaluationFloors_; // floor index per evaluation query
    std::optional<EvaluationReport> bestReport_;
    std::string bestWeights_; // torch archive of the best evaluated weights
    long bestEpisode_ = -1;   // episodes_ when they were evaluated
    std::vector<double> referenceCosts_;
    std::string referenceName_;
};

} // namespace fc

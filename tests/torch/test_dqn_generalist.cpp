// The generalist DQN model (issue 17, items 1 and 2): a graph network that scores graphs of
// any size, trained on several floors at once, compiled into the program, used by solver dqn
// without a model file, and the start of fine-tuning.
#include "DqnTestSupport.h"
#include "learning/GraphState.h"
#include "learning/dqn/DqnPolicy.h"
#include "learning/dqn/DqnSolver.h"
#include "learning/dqn/GeneralistModel.h"
#include "learning/dqn/PolicyBeam.h"
#include "learning/dqn/PolicySearch.h"
#include "model/SyntheticPlans.h"

#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <limits>
#include <sstream>

using namespace fc;

namespace {

using fc::test::preparedSample;
using fc::test::smallOptions;

// A graph-network observation of `corners` corners: feature 0 marks the valid ones.
std::vector<float> graphObservation(int corners, int channels, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<float> value(0.0f, 1.0f);
    std::vector<float> obs(static_cast<std::size_t>(corners * channels));
    for (int c = 0; c < corners; ++c) {
        obs[static_cast<std::size_t>(c * channels)] = c % 3 == 2 ? 0.0f : 1.0f;
        for (int f = 1; f < channels; ++f)
            obs[static_cast<std::size_t>(c * channels + f)] = value(rng);
    }
    return obs;
}

std::vector<char> maskOf(const std::vector<float>& obs, int channels) {
    std::vector<char> mask(obs.size() / static_cast<std::size_t>(channels));
    for (std::size_t c = 0; c < mask.size(); ++c)
        mask[c] = obs[c * static_cast<std::size_t>(channels)] > 0.5f ? 1 : 0;
    return mask;
}

DqnHyperParameters graphParameters() {
    DqnHyperParameters p;
    p.network = QNetworkKind::Graph;
    p.inputChannels = 6;
    p.hiddenUnits = 16;
    p.batchSize = 8;
    p.learningStarts = 4;
    p.targetSyncInterval = 10;
    p.seed = 3;
    return p;
}

std::vector<CornerGraph> generatedFloors() {
    std::vector<CornerGraph> floors;
    for (const Plan& plan : {generateHallWithObstacles(14.0, 9.0, 2, 3), generateOfficeFloor(3, 4)})
        floors.push_back(preparePlan(plan, RobotProfile{}, 90.0).graph);
    return floors;
}

} // namespace

// The same network scores a graph of 5 corners and one of 9, and padding a state with invalid
// corners (as mixed batches are) changes no Q value of its own corners.
TEST(GraphAgent, ScoresGraphsOfAnySizeAndTrainsOnMixedBatches) {
    const DqnHyperParameters p = graphParameters();
    DqnAgent agent(3, 9, p);
    ASSERT_TRUE(agent.sizeFree());
    const std::vector<float> small = graphObservation(5, p.inputChannels, 1);
    const std::vector<float> large = graphObservation(9, p.inputChannels, 2);
    const std::vector<float> qSmall = agent.qValues(small, 1);
    ASSERT_EQ(qSmall.size(), 5u);
    EXPECT_EQ(agent.qValues(large, 1).size(), 9u);
    std::vector<float> padded = small;
    padded.resize(large.size(), 0.0f);
    const std::vector<float> qPadded = agent.qValues(padded, 1);
    for (std::size_t a = 0; a < qSmall.size(); ++a)
        EXPECT_NEAR(qSmall[a], qPadded[a], 1e-5f) << "corner " << a;
    for (std::size_t a = qSmall.size(); a < qPadded.size(); ++a)
        EXPECT_EQ(qPadded[a], 0.0f);
    const int chosen = agent.greedyAction(small, maskOf(small, p.inputChannels));
    ASSERT_GE(chosen, 0);
    EXPECT_TRUE(maskOf(small, p.inputChannels)[static_cast<std::size_t>(chosen)]);

    // Transitions of both sizes in one memory; batches mix them.
    double lossSum = 0.0;
    int losses = 0;
    for (int i = 0; i < 40; ++i) {
        const bool big = i % 2 == 1;
        Transition t;
        t.observation = big ? large : small;
        t.action = 0;
        t.reward = -0.5f;
        t.nextObservation = big ? small : large; // sizes may differ between the two sides
        t.nextMask = maskOf(t.nextObservation, p.inputChannels);
        t.done = i % 5 == 4;
        const double loss = agent.observe(std::move(t));
        if (!std::isnan(loss)) {
            EXPECT_TRUE(std::isfinite(loss));
            lossSum += loss;
            ++losses;
        }
    }
    EXPECT_GT(losses, 30);
    EXPECT_TRUE(std::isfinite(lossSum));
    Transition wrong;
    wrong.observation = small;
    wrong.action = 7; // beyond its 5 corners
    wrong.nextObservation = large;
    wrong.nextMask = maskOf(large, p.inputChannels);
    EXPECT_THROW(agent.remember(std::move(wrong)), std::invalid_argument);
}

// A generalist trains on several floors, is saved as such, and plans a floor it never saw
// (no fingerprint refuses it), always finishing.
TEST(Generalist, TrainsOnSeveralFloorsAndPlansAnUnseenFloor) {
    TrainingOptions options = smallOptions(TrainingOptions::graph(2));
    options.evaluationQueries = 6;
    DqnTrainer trainer(generatedFloors(), options, 1.0, "a test");
    EXPECT_TRUE(trainer.generalist());
    EXPECT_EQ(trainer.train(40, 0.0), TrainingStop::EpisodeLimit);
    const EvaluationReport report = trainer.evaluate();
    EXPECT_EQ(report.queries, 6);
    EXPECT_EQ(report.failures, 0);

    std::istringstream in(fc::test::serialized(trainer));
    const DqnModel model = readDqnModel(in, "memory");
    EXPECT_TRUE(model.info.generalist);
    EXPECT_EQ(model.info.provenance, "a test");
    EXPECT_EQ(model.info.graphFingerprint, 0u);
    const PreparedPlan unseen = preparedSample("room-obstacle");
    EXPECT_NO_THROW(checkModelFitsGraph(model.info, unseen.graph, "memory"));
    const std::vector<Query> queries = randomQueries(unseen.graph, 3, 5, QuerySet::AllCells);
    for (const Query& q : queries) {
        const Solution s = solveWithPolicy(*model.agent, unseen.graph, q, model.info.environment,
                                           model.info.refinement);
        EXPECT_TRUE(evaluateWalk(unseen.graph, q, s.walk).coversAllRequired);
    }
    // Only the graph setting makes a generalist.
    EXPECT_THROW(DqnTrainer(generatedFloors(), smallOptions(TrainingOptions::improved(1)), 1.0, ""),
                 std::invalid_argument);
    EXPECT_THROW(DqnTrainer(std::vector<CornerGraph>{}, options, 1.0, ""), std::invalid_argument);
}

// The model compiled in loads, says how it was made, and solver dqn plans a sample plan with
// it when no model file is given, at the floor's own sweep angles.
TEST(Generalist, BuiltInModelPlansWithoutAModelFile) {
    const std::shared_ptr<const DqnModel> model = generalistModel();
    ASSERT_TRUE(model);
    EXPECT_TRUE(model->info.generalist);
    EXPECT_NE(model->info.provenance.find("floorcover-train-generalist"), std::string::npos);
    EXPECT_GT(model->info.episodes, 0);
    EXPECT_EQ(generalistModel().get(), model.get()); // parsed once

    registerDqnSolver();
    PlanRequest request;
    request.plan = fc::test::samplePlan("room-obstacle");
    request.solver = "dqn";
    const PlanResult result = planCoverage(request);
    EXPECT_EQ(result.solution.solver, "dqn");
    EXPECT_GE(result.metrics.coverage, 0.99);
}

// Fine-tuning starts from the generalist's weights (the same Q values before any step),
// explores less at first, and makes a model of this plan that says where it came from.
TEST(Generalist, FineTuningStartsFromItsWeights) {
    const PreparedPlan plan = preparedSample("simple");
    TrainingOptions options = TrainingOptions::graph(4);
    options.initialModel = generalistModel();
    DqnTrainer trainer(plan.graph, options, 90.0, 1.0);
    EXPECT_FALSE(trainer.options().initialModel); // not kept alive
    EXPECT_LE(trainer.agent().epsilon(), options.fineTuneEpsilon + 1e-12);
    CoverageEnvironment env(plan.graph, trainer.options().environment);
    std::mt19937_64 rng(8);
    const std::vector<float> obs = env.reset(rng);
    EXPECT_EQ(trainer.agent().qValues(obs, 1), generalistModel()->agent->qValues(obs, 1));
    trainer.train(5, 0.0);
    const DqnModelInfo info = trainer.modelInfo();
    EXPECT_FALSE(info.generalist);
    EXPECT_EQ(info.graphFingerprint, graphFingerprint(plan.graph));
    EXPECT_NE(info.provenance.find("generalist"), std::string::npos);

    // An image-setting run cannot start from it.
    TrainingOptions image = TrainingOptions::improved(4);
    image.initialModel = generalistModel();
    EXPECT_THROW(DqnTrainer(plan.graph, image, 90.0, 1.0), InputError);
}

// The policy as a search guide: width 1 is the greedy rollout, step for step; a wider beam
// covers every required cell, is never dearer than the rollout, and is cancellable.
TEST(PolicyBeam, WidthOneIsTheRolloutAndWiderBeamsFinish) {
    const std::shared_ptr<const DqnModel> model = generalistModel();
    const PreparedPlan plan = preparedSample("room-obstacle");
    double rolloutSum = 0.0, beamSum = 0.0;
    for (const Query& q : randomQueries(plan.graph, 8, 3, QuerySet::AllCells)) {
        const Solution rollout =
            solveWithPolicy(*model->agent, plan.graph, q, model->info.environment);
        const Solution one =
            policyBeamWalk(*model->agent, plan.graph, q, model->info.environment, 1);
        EXPECT_EQ(one.walk.nodes, rollout.walk.nodes);
        EXPECT_DOUBLE_EQ(one.graphCost, rollout.graphCost);
        const Solution four =
            policyBeamWalk(*model->agent, plan.graph, q, model->info.environment, 4);
        EXPECT_TRUE(evaluateWalk(plan.graph, q, four.walk).coversAllRequired);
        EXPECT_LE(four.graphCost, rollout.graphCost + 1e-9);
        rolloutSum += rollout.graphCost;
        beamSum += four.graphCost;
    }
    std::printf("room-obstacle, 8 queries: rollout %.1f, beam of 4 %.1f (graph cost)\n", rolloutSum,
                beamSum);
    const Query q = randomQueries(plan.graph, 1, 4, QuerySet::AllCells).front();
    SolveControl cancelled;
    cancelled.cancelled = [] { return true; };
    EXPECT_THROW(
        policyBeamWalk(*model->agent, plan.graph, q, model->info.environment, 4, cancelled),
        SolverError);
    EXPECT_THROW(policyBeamWalk(*model->agent, plan.graph, q, model->info.environment, 0),
                 std::invalid_argument);
}

// The policy-guided search: its moves replay a prefix of the best walk and let the policy
// finish it; it never answers worse than its start (the beam's refined walk), always covers
// the query, and a cancellation ends it with its best complete walk.
TEST(PolicySearch, MovesKeepTheBestCompleteWalk) {
    const std::shared_ptr<const DqnModel> model = generalistModel();
    const PreparedPlan plan = preparedSample("office");
    const Query q = randomQueries(plan.graph, 1, 11, QuerySet::RoomSubsets).front();
    const EnvironmentOptions& env = model->info.environment;
    const Solution start =
        solveWithPolicy(*model->agent, plan.graph, q, env, model->info.refinement, {}, 4);
    // The entry corners replay the walk's cell order exactly.
    const std::vector<int> actions = entryActions(plan.graph, q, start.walk);
    CoverageEnvironment replay(plan.graph, env);
    replay.reset(q);
    for (int a : actions)
        replay.step(a);
    EXPECT_TRUE(replay.done());
    EXPECT_EQ(evaluateWalk(plan.graph, q, replay.walk()).cellOrder, start.cellOrder);

    PolicySearchOptions options;
    options.maxMoves = 12;
    const Solution searched =
        policyGuidedSearch(*model->agent, plan.graph, q, env, model->info.refinement, {}, options);
    EXPECT_LE(searched.graphCost, start.graphCost + 1e-9);
    EXPECT_TRUE(evaluateWalk(plan.graph, q, searched.walk).coversAllRequired);
    EXPECT_EQ(searched.solver, "dqn");

    // Cancelled during the moves: the best walk so far comes back. The start polls the same
    // number of times on every run (deterministic), so the cut falls after it.
    int startPolls = 0;
    SolveControl counting;
    counting.cancelled = [&startPolls] { return ++startPolls < 0; };
    solveWithPolicy(*model->agent, plan.graph, q, env, model->info.refinement, counting, 4);
    int polls = 0;
    SolveControl control;
    control.cancelled = [&polls, startPolls] { return ++polls > startPolls + 200; };
    options.maxMoves = 0;
    const Solution cut = policyGuidedSearch(*model->agent, plan.graph, q, env,
                                            model->info.refinement, control, options);
    EXPECT_TRUE(evaluateWalk(plan.graph, q, cut.walk).coversAllRequired);
    EXPECT_THROW(
        policyGuidedSearch(*model->agent, plan.graph, q, env, model->info.refinement, {}, options),
        std::invalid_argument);
}

// The best evaluated weights are kept: weights trained further but not evaluated since give
// way to them, and once they are back their evaluation repeats exactly.
TEST(DqnTrainer, RestoresTheBestEvaluatedWeights) {
    const PreparedPlan plan = preparedSample("simple");
    TrainingOptions options = smallOptions(TrainingOptions::graph(6));
    options.evaluationQueries = 8;
    DqnTrainer trainer(plan.graph, options, 90.0, 1.0);
    EXPECT_FALSE(trainer.restoreBestEvaluated()); // nothing evaluated yet
    const EvaluationReport first = trainer.evaluate();
    EXPECT_EQ(trainer.bestEvaluatedEpisode(), 0);
    EXPECT_FALSE(trainer.restoreBestEvaluated()); // the current weights are the best
    CoverageEnvironment env(plan.graph, trainer.options().environment);
    std::mt19937_64 rng(5);
    const std::vector<float> obs = env.reset(rng);
    const std::vector<float> q0 = trainer.agent().qValues(obs, 1);
    trainer.train(60, 0.0);
    ASSERT_NE(trainer.agent().qValues(obs, 1), q0);
    EXPECT_TRUE(trainer.restoreBestEvaluated());
    EXPECT_EQ(trainer.agent().qValues(obs, 1), q0);
    EXPECT_EQ(trainer.episodes(), 60); // the counters stay
    const EvaluationReport again = trainer.evaluate();
    EXPECT_DOUBLE_EQ(again.meanGap, first.meanGap);
    ASSERT_TRUE(trainer.bestEvaluation().has_value());
    EXPECT_DOUBLE_EQ(trainer.bestEvaluation()->meanGap, first.meanGap);
}

// The graph state's "nearest other uncovered cell" and "uncovered cells near" features come
// from a bucket grid; they must equal the full scan over every uncovered cell exactly (a
// trained model depends on them), here on a 40-room floor at random covered sets.
TEST(GraphState, BucketedNearestCellsEqualTheFullScan) {
    const PreparedPlan plan = preparePlan(generateOfficeFloor(40, 9), RobotProfile{}, 90.0);
    const CornerGraph& g = plan.graph;
    const GraphStateTables tables(g);
    const double edge = std::max(g.maxEdgeLength, 1e-9);
    std::mt19937_64 rng(3);
    std::vector<double> transit(g.nodes.size(), 1.0), toEnd(g.nodes.size(), 1.0);
    for (double share : {0.05, 0.5, 0.97}) {
        std::vector<char> covered(g.cells.size(), 0);
        std::bernoulli_distribution cover(share);
        for (char& c : covered)
            c = cover(rng) ? 1 : 0;
        const std::vector<char> initial(g.cells.size(), 0);
        GraphStateInput in{0, 1, &covered, &initial, &transit, &toEnd};
        const std::vector<float> f = graphStateFeatures(g, tables, in);
        for (const GraphNode& n : g.nodes) {
            if (n.cell < 0 || covered[static_cast<std::size_t>(n.cell)])
                continue; // not a valid corner: the network does not read its features
            const int exit = tables.exitNode[static_cast<std::size_t>(n.id)];
            const Vec2 from =
                exit >= 0 ? g.nodes[static_cast<std::size_t>(exit)].position : n.position;
            double nearest = std::numeric_limits<double>::infinity();
            int near = 0;
            for (std::size_t c = 0; c < g.cells.size(); ++c) {
                if (covered[c] || static_cast<int>(c) == n.cell)
                    continue;
                const double d = distance(from, tables.cellCentre[c]);
                nearest = std::min(nearest, d);
                near += d <= 2.0 * edge ? 1 : 0;
            }
            const float* row = f.data() + static_cast<std::size_t>(n.id) * kGraphFeatureCount;
            const float expected9 =
                nearest < std::numeric_limits<double>::infinity()
                    ? static_cast<float>(std::min(nearest / (edge * kGraphCostUnit), kGraphCostCap))
                    : 0.0f;
            ASSERT_EQ(row[9], expected9) << "node " << n.id << ", share " << share;
            ASSERT_EQ(row[13], std::min(1.0f, static_cast<float>(near) / 8.0f)) << n.id;
        }
    }
}

// Thorough moves: every walk of the policy is searched by the heuristic's whole search from
// its order (searchFromWalk), never worse than the walk it starts from; a walk that misses a
// required cell is refused; a search cut short at once answers the policy's own walk.
TEST(PolicySearch, ThoroughMovesSearchFromThePolicysWalks) {
    const std::shared_ptr<const DqnModel> model = generalistModel();
    const PreparedPlan plan = preparedSample("office");
    const Query q = randomQueries(plan.graph, 1, 12, QuerySet::RoomSubsets).front();
    const EnvironmentOptions& env = model->info.environment;
    const Solution rollout =
        solveWithPolicy(*model->agent, plan.graph, q, env, OrderRefinement::None);
    const Solution searched = searchFromWalk(plan.graph, q, rollout);
    EXPECT_LE(searched.graphCost, rollout.graphCost + 1e-9);
    EXPECT_TRUE(evaluateWalk(plan.graph, q, searched.walk).coversAllRequired);
    EXPECT_DOUBLE_EQ(searchFromWalk(plan.graph, q, rollout).graphCost, searched.graphCost);

    PolicySearchOptions options;
    options.thorough = true;
    options.beamWidth = 1;
    options.maxMoves = 3;
    const Solution best = policyGuidedSearch(*model->agent, plan.graph, q, env,
                                             model->info.refinement, {}, options, &rollout);
    EXPECT_LE(best.graphCost, rollout.graphCost + 1e-9);
    EXPECT_TRUE(evaluateWalk(plan.graph, q, best.walk).coversAllRequired);
    std::printf("office query: policy %.1f, searched from it %.1f, 3 thorough moves %.1f\n",
                rollout.graphCost, searched.graphCost, best.graphCost);

    SolveControl now;
    now.cancelled = [] { return true; };
    const Solution cut = policyGuidedSearch(*model->agent, plan.graph, q, env,
                                            model->info.refinement, now, options, &rollout);
    EXPECT_EQ(cut.walk.nodes, rollout.walk.nodes);

    Solution partial = rollout;
    partial.cellOrder.resize(partial.cellOrder.size() / 2);
    EXPECT_THROW(searchFromWalk(plan.graph, q, partial), SolverError);
}

// Learning from demonstrations: expert walks replayed into the agent's demonstration set
// (never mixed with its own memory), and pre-training on them makes the policy rank the
// expert's corner first more often than before.
TEST(DqnTrainer, DemonstrationsTeachTheExpertsCorners) {
    const PreparedPlan plan = preparedSample("room-obstacle");
    TrainingOptions options = smallOptions(TrainingOptions::graph(3));
    DqnTrainer trainer(plan.graph, options, 90.0, 1.0);
    const long added = trainer.addDemonstrations(12);
    EXPECT_GT(added, 12);
    EXPECT_EQ(trainer.agent().demonstrationCount(), static_cast<std::size_t>(added));
    EXPECT_EQ(trainer.agent().memory().size(), 0u);
    auto imitation = [&trainer] {
        const DqnAgent& agent = trainer.agent();
        const ReplayMemory& demos = agent.demonstrations();
        const auto channels = static_cast<std::size_t>(agent.parameters().inputChannels);
        int first = 0;
        for (std::size_t i = 0; i < demos.size(); ++i) {
            const Transition& t = demos.at(i);
            const std::vector<float> q = agent.qValues(t.observation, 1);
            int best = -1;
            for (std::size_t c = 0; c < q.size(); ++c)
                if (t.observation[c * channels] > 0.5f &&
                    (best < 0 || q[c] > q[static_cast<std::size_t>(best)]))
                    best = static_cast<int>(c);
            first += best == t.action ? 1 : 0;
        }
        return static_cast<double>(first) / static_cast<double>(demos.size());
    };
    const double before = imitation();
    trainer.pretrain(1500);
    const double after = imitation();
    std::printf("room-obstacle: expert corner ranked first in %.0f%% of %ld demonstration "
                "states before pre-training, %.0f%% after\n",
                100.0 * before, added, 100.0 * after);
    EXPECT_GT(after, before + 0.15);

    TrainingOptions image = smallOptions(TrainingOptions::improved(3));
    DqnTrainer imageTrainer(plan.graph, image, 90.0, 1.0);
    EXPECT_THROW(imageTrainer.addDemonstrations(2), std::invalid_argument);
}

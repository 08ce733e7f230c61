// The Double-DQN planner end to end below the CLI: training loop, model file, refusal of a
// mismatched or broken model, masked inference, the "dqn" solver in the pipeline.
#include "DqnTestSupport.h"
#include "formats/PlanIO.h"
#include "learning/dqn/DqnModelFile.h"
#include "learning/dqn/DqnPolicy.h"
#include "learning/dqn/DqnSolver.h"
#include "learning/dqn/DqnTrainer.h"
#include "pipeline/Planner.h"

#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <sstream>

using namespace fc;

namespace {

using fc::test::samplePlan;
using fc::test::serialized;
using fc::test::smallOptions;

constexpr long kLearningEpisodes = 2000;

PreparedPlan prepared(const std::string& name) {
    return fc::test::preparedSample(name);
}

// Q values on a few fixed states (the archives' bytes differ between runs: torch mangles
// module names with a process-wide counter).
std::vector<float> probeQValues(const DqnTrainer& trainer) {
    CoverageEnvironment env(trainer.graph(), trainer.options().environment);
    std::mt19937_64 rng(99);
    std::vector<float> all;
    for (int i = 0; i < 4; ++i) {
        const std::vector<float> q = trainer.agent().qValues(env.reset(rng), 1);
        all.insert(all.end(), q.begin(), q.end());
    }
    return all;
}

std::vector<double> rewardsOf(DqnTrainer& trainer, long episodes) {
    std::vector<double> rewards;
    trainer.train(episodes, 0.0, [&](const TrainingProgress& p) { rewards.push_back(p.reward); });
    return rewards;
}

} // namespace

TEST(DqnTrainer, ReportsProgressAndIsReproducible) {
    const PreparedPlan plan = prepared("simple");
    DqnTrainer first(plan.graph, smallOptions(TrainingOptions::improved(3)));
    std::vector<TrainingProgress> reports;
    const TrainingStop stop =
        first.train(40, 0.0, [&](const TrainingProgress& p) { reports.push_back(p); });
    EXPECT_EQ(stop, TrainingStop::EpisodeLimit);
    ASSERT_EQ(reports.size(), 40u);
    EXPECT_EQ(reports.back().episode, 40);
    EXPECT_GT(reports.back().totalSteps, 40);
    EXPECT_LT(reports.back().epsilon, 1.0);
    EXPECT_FALSE(std::isnan(reports.back().loss)); // learning started
    double sum = 0.0;
    for (const TrainingProgress& p : reports)
        sum += p.reward;
    EXPECT_NEAR(reports.back().movingAverage, sum / 40.0, 1e-9); // window 100 > 40 episodes

    std::vector<double> expected;
    for (const TrainingProgress& p : reports)
        expected.push_back(p.reward);
    DqnTrainer second(plan.graph, smallOptions(TrainingOptions::improved(3)));
    EXPECT_EQ(rewardsOf(second, 40), expected);
    EXPECT_EQ(probeQValues(first), probeQValues(second)); // the same network
    DqnTrainer otherSeed(plan.graph, smallOptions(TrainingOptions::improved(4)));
    EXPECT_NE(rewardsOf(otherSeed, 40), expected);
}

TEST(DqnTrainer, CancelsBetweenEpisodesAndResumesFromAModel) {
    const PreparedPlan plan = prepared("simple");
    DqnTrainer trainer(plan.graph, smallOptions(TrainingOptions::paper(5)));
    int calls = 0;
    const TrainingStop stop = trainer.train(
        0, 0.0, [&](const TrainingProgress&) { ++calls; }, [&] { return calls >= 3; });
    EXPECT_EQ(stop, TrainingStop::Cancelled);
    EXPECT_EQ(trainer.episodes(), 3);
    EXPECT_THROW(trainer.train(0, 0.0), std::invalid_argument); // would never stop
    trainer.train(20, 0.0);

    std::istringstream in(serialized(trainer));
    DqnTrainer resumed(plan.graph, readDqnModel(in, "memory"), "memory");
    EXPECT_EQ(resumed.episodes(), 23);
    EXPECT_EQ(resumed.agent().stepCount(), trainer.agent().stepCount());
    EXPECT_EQ(resumed.options().setting, "paper");
    EXPECT_FALSE(resumed.options().agent.maskActions);
    resumed.train(5, 0.0);
    EXPECT_EQ(resumed.episodes(), 28);
    EXPECT_GT(resumed.agent().stepCount(), trainer.agent().stepCount());
}

// A cancelled evaluation throws and keeps no partial reference costs: the next one measures
// exactly what an uncancelled one does.
TEST(DqnTrainer, EvaluationIsCancellableAndKeepsNoPartialReferences) {
    const PreparedPlan plan = prepared("room-obstacle");
    DqnTrainer trainer(plan.graph, smallOptions(TrainingOptions::graph(6)));
    trainer.train(5, 0.0);
    int checks = 0;
    SolveControl control;
    control.cancelled = [&checks] { return ++checks > 3; }; // during the reference solutions
    EXPECT_THROW(trainer.evaluate(control), SolverError);
    const EvaluationReport after = trainer.evaluate();
    DqnTrainer same(plan.graph, smallOptions(TrainingOptions::graph(6)));
    same.train(5, 0.0);
    const EvaluationReport fresh = same.evaluate();
    EXPECT_EQ(after.queries, fresh.queries);
    EXPECT_EQ(after.failures, 0);
    EXPECT_DOUBLE_EQ(after.meanGap, fresh.meanGap);
    EXPECT_DOUBLE_EQ(after.meanRefinedGap, fresh.meanRefinedGap);
    EXPECT_LE(after.meanRefinedGap, after.meanGap + 1e-12);
}

TEST(DqnModelFile, RoundTripKeepsPolicyAndMetadata) {
    const PreparedPlan plan = prepared("room-obstacle");
    TrainingOptions options = smallOptions(TrainingOptions::improved(7));
    options.nStep = 3; // a non-default value must round-trip too
    DqnTrainer trainer(plan.graph, options, 90.0, 1.0);
    trainer.train(15, 0.0);
    std::istringstream in(serialized(trainer));
    const DqnModel model = readDqnModel(in, "memory");
    EXPECT_EQ(model.info.setting, "improved");
    EXPECT_EQ(model.info.graphFingerprint, graphFingerprint(plan.graph));
    EXPECT_EQ(model.info.nodeCount, static_cast<int>(plan.graph.nodes.size()));
    EXPECT_EQ(model.info.episodes, 15);
    EXPECT_EQ(model.info.nStep, 3);
    EXPECT_EQ(model.info.refinement, OrderRefinement::LocalSearch);
    EXPECT_TRUE(model.info.environment.rewardIsNegativeGraphCost);
    EXPECT_TRUE(model.info.environment.costChannels);
    EXPECT_EQ(model.info.agent.inputChannels, 5);
    EXPECT_EQ(model.info.agent.hiddenUnits, 32);
    EXPECT_EQ(model.agent->stepCount(), trainer.agent().stepCount());
    for (const Query& q : randomQueries(plan.graph, 5, 9, QuerySet::AllCells)) {
        const Solution a = solveWithPolicy(trainer.agent(), plan.graph, q, options.environment);
        const Solution b = solveWithPolicy(*model.agent, plan.graph, q, model.info.environment);
        EXPECT_EQ(a.walk.nodes, b.walk.nodes);
    }
    EXPECT_NO_THROW(checkModelFitsGraph(model.info, plan.graph, "memory"));
}

TEST(DqnModelFile, RefusesAnotherPlanAndBrokenFiles) {
    const PreparedPlan simple = prepared("simple");
    DqnTrainer trainer(simple.graph, smallOptions(TrainingOptions::improved(1)));
    trainer.train(2, 0.0);
    const std::string bytes = serialized(trainer);

    const DqnModelInfo info = trainer.modelInfo();
    const PreparedPlan other = prepared("room-obstacle");
    try {
        checkModelFitsGraph(info, other.graph, "simple.fcdqn");
        FAIL() << "a model for another plan was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("simple.fcdqn"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("another floor plan"), std::string::npos);
    }
    // The same plan swept at another angle or with another width is another graph.
    const PreparedPlan turned = preparePlan(samplePlan("simple"), RobotProfile{}, 0.0);
    EXPECT_THROW(checkModelFitsGraph(info, turned.graph, "m"), InputError);
    EXPECT_THROW(DqnTrainer(
                     other.graph,
                     [&] {
                         std::istringstream in(bytes);
                         return readDqnModel(in, "m");
                     }(),
                     "m"),
                 InputError);

    auto expectRefused = [](const std::string& text, const std::string& words) {
        std::istringstream in(text);
        try {
            readDqnModel(in, "broken.fcdqn");
            ADD_FAILURE() << "accepted: " << text.substr(0, 40);
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("broken.fcdqn"), std::string::npos);
        }
    };
    expectRefused("", "not a FloorCover DQN model");
    expectRefused("{\"type\":\"FeatureCollection\"}", "not a FloorCover DQN model");
    expectRefused("FLOORCOVER-DQN 99\n{}\n", "version 99");
    expectRefused("FLOORCOVER-DQN 1\n{\"format_version\":1}\n", "corrupt model metadata");
    // Cut anywhere: a clear error, never a crash.
    for (std::size_t cut : {std::size_t{20}, bytes.find('\n', 20) + 1, bytes.size() / 2,
                            bytes.size() - 30, bytes.size() - 2})
        expectRefused(bytes.substr(0, cut), "");
    std::string flipped = bytes;
    flipped[flipped.size() / 2] ^= 0x5a; // inside the weights archive
    std::istringstream in(flipped);
    try {
        readDqnModel(in, "flipped");
    } catch (const InputError&) {
        // a corrupt archive is refused; a flipped float value may legitimately load
    }
}

TEST(DqnPolicy, MaskedInferenceAlwaysFinishesEvenUntrained) {
    const PreparedPlan plan = prepared("room-obstacle");
    for (const TrainingOptions& options :
         {smallOptions(TrainingOptions::paper(2)), smallOptions(TrainingOptions::improved(2))}) {
        DqnTrainer trainer(plan.graph, options); // untrained: arbitrary Q values
        for (const QuerySet kind : {QuerySet::AllCells, QuerySet::RoomSubsets}) {
            for (const Query& q : randomQueries(plan.graph, 25, 11, kind)) {
                const Solution s =
                    solveWithPolicy(trainer.agent(), plan.graph, q, options.environment);
                const WalkEvaluation e = evaluateWalk(plan.graph, q, s.walk);
                EXPECT_TRUE(e.connected && e.coversAllRequired);
                EXPECT_EQ(s.walk.nodes.front(), q.startNode);
                EXPECT_EQ(s.walk.nodes.back(), q.endNode);
                EXPECT_DOUBLE_EQ(s.graphCost, e.graphCost);
                const Solution refined =
                    solveWithPolicy(trainer.agent(), plan.graph, q, options.environment,
                                    OrderRefinement::LocalSearch);
                EXPECT_LE(refined.graphCost, s.graphCost + 1e-9);
                EXPECT_GE(refined.graphCost, solveExact(plan.graph, q).graphCost - 1e-9);
            }
        }
    }
}

TEST(DqnSolver, PlansThroughThePipelineWithTheModelsAngle) {
    registerDqnSolver();
    const auto names = solverNames();
    EXPECT_NE(std::find(names.begin(), names.end(), "dqn"), names.end());
    const std::string modelPath = ::testing::TempDir() + "fc-simple-model.fcdqn";
    {
        const PreparedPlan plan = preparePlan(samplePlan("simple"), RobotProfile{}, 0.0);
        DqnTrainer trainer(plan.graph, smallOptions(TrainingOptions::improved(1)), 0.0, 1.0);
        trainer.train(10, 0.0);
        trainer.save(modelPath);
    }
    PlanRequest request;
    request.plan = samplePlan("simple");
    request.solver = "dqn";
    request.modelPath = modelPath;
    request.sweep.automatic = true; // the model's angle, 0, is used
    const PlanResult result = planCoverage(request);
    EXPECT_EQ(result.solution.solver, "dqn");
    EXPECT_DOUBLE_EQ(result.stripeAngleDeg, 0.0);
    EXPECT_GE(result.metrics.coverage, 0.99);

    request.sweep.automatic = false;
    request.sweep.perRoom = false;
    request.sweep.angleDeg = 90.0; // another graph: refused with the model named
    try {
        planCoverage(request);
        FAIL() << "the model was used for another graph";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(modelPath), std::string::npos);
    }
    request.modelPath = ::testing::TempDir() + "no-such-model.fcdqn";
    EXPECT_THROW(planCoverage(request), InputError);
}

// Learning that silently stops working must fail CI (issue 17, item 4): on a small plan,
// seeded, the graph setting's policy alone (no refinement) gets far closer to the reference
// after a couple of thousand training episodes than before training. By hand with
// floorcover-dqn-report on simple: 104% mean gap after 0.5 s of training, 11.8% after 20 s.
TEST(DqnLearning, TrainingLowersThePolicyAloneGapByAClearMargin) {
    const PreparedPlan plan = prepared("simple");
    DqnTrainer trainer(plan.graph, TrainingOptions::graph(5));
    const EvaluationReport before = trainer.evaluate();
    ASSERT_GT(before.queries, 10);
    EXPECT_EQ(trainer.train(kLearningEpisodes, 0.0), TrainingStop::EpisodeLimit);
    const EvaluationReport after = trainer.evaluate();
    std::printf("policy alone on simple: mean gap %.1f%% untrained, %.1f%% after %ld episodes\n",
                100.0 * before.meanGap, 100.0 * after.meanGap, kLearningEpisodes);
    EXPECT_EQ(after.failures, 0);
    // Here 221% untrained, 30% after 2,000 episodes (6.5 s); a learner that stopped learning
    // stays near where it began.
    EXPECT_LT(after.meanGap, 0.25 * before.meanGap);
    EXPECT_LT(after.meanGap, 0.5);
}

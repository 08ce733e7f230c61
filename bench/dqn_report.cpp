// floorcover-dqn-report: trains the Double-DQN planner in the paper's, the improved and the
// graph-state setting on sample plans under a fixed time budget (one thread), records learning
// curves and measures the gap to exact/heuristic on 100 random queries.
//   floorcover-dqn-report [--seconds S] [--seed N] [--queries N] [--cases a,b]
//                         [--settings paper,improved,improved+gamma=1,...] --out DIR
//   floorcover-dqn-report --model FILE --cases NAME [--refine none|corners|local-search]
//   floorcover-dqn-report --model generalist --cases a,b   (the built-in generalist)
// A case is a sample plan's name or generated-office-N (a generated floor of N rooms).
// A setting is "paper", "improved" or "graph", optionally followed by "+key=value" changes (an
// ablation): state=image|graph (the state and its network), mask=0|1, reward=paper|cost, nstep=N,
// gamma=G, lr=R, eps=STEPS, net=paper|small, refine=none|corners|local-search, cost=SCALE (reward
// per longest edge), sync=STEPS, batch=N, features=0|1, graphfeatures=14|16, conv=C (all three
// layers), hidden=N, init=generalist (fine-tune the built-in generalist), fteps=E (its first
// epsilon), starts=N (steps before the first gradient step), messages=N (message rounds of the
// graph network), demos=N and pretrain=STEPS (N expert walks of the plan and STEPS gradient
// steps on them before training, DQfD), demoshare=F (their share of later batches). Writes
// DIR/curves-<case>-<setting>.csv and prints a Markdown table (docs/dqn.md). Time is the
// training thread's CPU time, so a busy machine does not change the figures.
#include "BenchSupport.h"
#include "formats/PlanIO.h"
#include "learning/dqn/DqnModelFile.h"
#include "learning/dqn/DqnPolicy.h"
#include "learning/dqn/DqnTrainer.h"
#include "learning/dqn/GeneralistModel.h"
#include "learning/dqn/PolicyBeam.h"
#include "model/SyntheticPlans.h"
#include "pipeline/Planner.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace fc;

namespace {

struct Case {
    std::string plan;
    QuerySet queries;
};

struct Options {
    double seconds = 300.0;
    std::uint64_t seed = 1;
    int queries = 100;
    std::vector<std::string> cases{"simple", "room-obstacle", "office"};
    std::vector<std::string> settings{"paper", "improved"};
    std::string out = ".";
    std::string model;      // measure this saved model instead of training
    std::string refinement; // with --model: override the model's refinement
};

using fc::bench::splitList;

// The integer value of "+key=N" in a setting, or `fallback`.
long settingValue(const std::string& setting, const std::string& key, long fallback) {
    const std::string token = "+" + key + "=";
    const std::size_t at = setting.find(token);
    return at == std::string::npos ? fallback : std::stol(setting.substr(at + token.size()));
}

TrainingOptions settingOptions(const std::string& setting, std::uint64_t seed) {
    const std::vector<std::string> parts = [&] {
        std::vector<std::string> out;
        std::stringstream in(setting);
        for (std::string item; std::getline(in, item, '+');)
            out.push_back(item);
        return out;
    }();
    TrainingOptions o = TrainingOptions::named(parts.at(0), seed);
    const TrainingOptions paper = TrainingOptions::paper(seed);
    for (std::size_t i = 1; i < parts.size(); ++i) {
        const std::string key = parts[i].substr(0, parts[i].find('='));
        const std::string value = parts[i].substr(parts[i].find('=') + 1);
        if (key == "mask")
            o.agent.maskActions = o.agent.maskTargetArgmax = value == "1";
        else if (key == "reward") {
            const bool cost = value == "cost";
            const bool features = o.environment.costChannels;
            o.environment = cost ? TrainingOptions::improved(seed).environment : paper.environment;
            o.environment.costChannels = features; // a separate lever
        } else if (key == "nstep")
            o.nStep = std::stoi(value);
        else if (key == "gamma")
            o.agent.gamma = std::stod(value);
        else if (key == "lr")
            o.agent.learningRate = std::stod(value);
        else if (key == "eps")
            o.agent.epsilonDecaySteps = std::stol(value);
        else if (key == "sync")
            o.agent.targetSyncInterval = std::stoi(value);
        else if (key == "batch")
            o.agent.batchSize = std::stoi(value);
        else if (key == "net") {
            const DqnHyperParameters& from =
                value == "paper" ? paper.agent : TrainingOptions::improved(seed).agent;
            o.agent.conv1Channels = from.conv1Channels;
            o.agent.conv2Channels = from.conv2Channels;
            o.agent.conv3Channels = from.conv3Channels;
            o.agent.hiddenUnits = from.hiddenUnits;
        } else if (key == "conv")
            o.agent.conv1Channels = o.agent.conv2Channels = o.agent.conv3Channels =
                std::stoi(value);
        else if (key == "cost")
            o.environment.costScale = std::stod(value);
        else if (key == "hidden")
            o.agent.hiddenUnits = std::stoi(value);
        else if (key == "messages")
            o.agent.messageRounds = std::stoi(value);
        else if (key == "features")
            o.environment.costChannels = value == "1";
        else if (key == "state") {
            const TrainingOptions from =
                value == "graph" ? TrainingOptions::graph(seed) : TrainingOptions::improved(seed);
            o.environment.graphState = from.environment.graphState;
            o.environment.costChannels = from.environment.costChannels;
            o.agent.network = from.agent.network;
            o.agent.hiddenUnits = from.agent.hiddenUnits;
            o.agent.replayCapacity = from.agent.replayCapacity;
        } else if (key == "graphfeatures")
            o.environment.graphFeatures = std::stoi(value);
        else if (key == "refine")
            o.refinement = refinementFromName(value);
        else if (key == "best" || key == "demos" || key == "pretrain")
            continue; // read by the training loop
        else if (key == "demoshare")
            o.agent.demonstrationShare = std::stod(value);
        else if (key == "fteps")
            o.fineTuneEpsilon = std::stod(value);
        else if (key == "starts")
            o.agent.learningStarts = std::stoi(value);
        else if (key == "init" && value == "generalist")
            o.initialModel = generalistModel(); // fine-tuning (issue 17, item 2)
        else
            throw std::invalid_argument("unknown setting change " + key);
    }
    o.setting = setting;
    return o;
}

using fc::bench::threadCpuSeconds;

struct FinalFigures {
    int queries = 0, failures = 0, exactReferences = 0;
    double meanGap = 0, maxGap = 0, meanRefinedGap = 0, maxRefinedGap = 0, greedyGap = 0;
    double refinedGreedyGap = 0; // greedy's walk under the same refinement: what the policy adds
    double beamGap = 0,
           refinedBeamGap = 0; // the policy's beam search (PolicyBeam.h), alone / refined
    double beamMs = 0;         // the beam + refinement per query
    double meanMs = 0, maxMs = 0;
};

// Plans `queries` random queries with the trained policy (raw and as the dqn solver, i.e.
// with the model's refinement) and compares with the exact optimum (<= 12 cells) or the
// heuristic solver.
FinalFigures measure(const DqnAgent& agent, const CornerGraph& graph,
                     const EnvironmentOptions& environment, OrderRefinement refinement,
                     const Case& c, int count, std::uint64_t seed) {
    FinalFigures f;
    for (const Query& q : randomQueries(graph, count, seed * 1000003ULL + 17ULL, c.queries)) {
        const int cells = static_cast<int>(std::count(q.required.begin(), q.required.end(), 1));
        const bool exact = cells <= 12;
        const double tRef = threadCpuSeconds();
        const double reference = std::max(
            exact ? solveExact(graph, q).graphCost : solveHeuristic(graph, q).graphCost, 1e-9);
        const double referenceMs = 1000.0 * (threadCpuSeconds() - tRef);
        f.exactReferences += exact ? 1 : 0;
        ++f.queries;
        try {
            const double tRaw = threadCpuSeconds();
            const Solution raw = solveWithPolicy(agent, graph, q, environment);
            const double rawMs = 1000.0 * (threadCpuSeconds() - tRaw);
            const double t0 = threadCpuSeconds();
            const Solution solved = solveWithPolicy(agent, graph, q, environment, refinement);
            const double ms = 1000.0 * (threadCpuSeconds() - t0);
            f.meanMs += ms;
            f.maxMs = std::max(f.maxMs, ms);
            const double gap = raw.graphCost / reference - 1.0;
            const double refined = solved.graphCost / reference - 1.0;
            f.meanGap += gap;
            f.maxGap = std::max(f.maxGap, gap);
            f.meanRefinedGap += refined;
            f.maxRefinedGap = std::max(f.maxRefinedGap, refined);
            const Solution greedy = solveGreedy(graph, q);
            f.greedyGap += greedy.graphCost / reference - 1.0;
            const double greedyRefined =
                refineCellOrder(graph, q, greedy, refinement, kPolicyRefinementBudget).graphCost /
                    reference -
                1.0;
            f.refinedGreedyGap += greedyRefined;
            const double tBeam = threadCpuSeconds();
            const Solution beamWalk =
                policyBeamWalk(agent, graph, q, environment, kPolicyBeamWidth);
            const Solution beamRefined =
                refineCellOrder(graph, q, beamWalk, refinement, kPolicyRefinementBudget);
            f.beamMs += 1000.0 * (threadCpuSeconds() - tBeam);
            f.beamGap += beamWalk.graphCost / reference - 1.0;
            f.refinedBeamGap += beamRefined.graphCost / reference - 1.0;
            if (std::getenv("FC_DQN_REPORT_QUERIES"))
                std::fprintf(stderr,
                             "query cells=%d ref=%.1f policy=%.3f dqn=%.3f greedy=%.3f "
                             "greedy+refine=%.3f ms=%.1f policyms=%.1f refms=%.1f\n",
                             cells, reference, gap, refined, greedy.graphCost / reference - 1.0,
                             greedyRefined, ms, rawMs, referenceMs);
        } catch (const SolverError& e) {
            ++f.failures;
            std::cerr << "failure: " << e.what() << "\n";
        }
    }
    const int ok = std::max(1, f.queries - f.failures);
    f.meanGap /= ok;
    f.meanRefinedGap /= ok;
    f.greedyGap /= ok;
    f.refinedGreedyGap /= ok;
    f.beamGap /= ok;
    f.refinedBeamGap /= ok;
    f.beamMs /= ok;
    f.meanMs /= ok;
    return f;
}

const std::string kGenerated = "generated-office-";

bool isGenerated(const std::string& name) {
    return name.rfind(kGenerated, 0) == 0;
}

// A sample plan by name, or "generated-office-N": generateOfficeFloor(N rooms, seed), an
// unseen plan for a sanity check.
Project loadCase(const std::string& name, std::uint64_t seed) {
    if (!isGenerated(name))
        return loadProjectFile(std::string(FC_PLANS_DIR) + "/" + name + ".geojson");
    Project project;
    project.plan = generateOfficeFloor(std::stoi(name.substr(kGenerated.size())), seed);
    return project;
}

void printRow(const std::string& name, const std::string& setting, long episodes, long steps,
              const FinalFigures& f) {
    const char* reference = f.exactReferences == f.queries ? "exact"
                            : f.exactReferences == 0       ? "heuristic"
                                                           : "exact/heuristic";
    std::printf("| %s | %s | %ld | %ld | %.2f%% | %.1f%% | %.2f%% | %.2f%% | %.2f%% | %.2f%% | "
                "%.2f%% | %.2f%% | %d/%d | %s | %.1f (%.1f) | %.1f |\n",
                name.c_str(), setting.c_str(), episodes, steps, 100 * f.meanGap, 100 * f.maxGap,
                100 * f.meanRefinedGap, 100 * f.maxRefinedGap, 100 * f.greedyGap,
                100 * f.refinedGreedyGap, 100 * f.beamGap, 100 * f.refinedBeamGap, f.failures,
                f.queries, reference, f.meanMs, f.maxMs, f.beamMs);
    std::fflush(stdout);
}

Case caseOf(const std::string& name) {
    return Case{name, name == "office" || name == "ward" || isGenerated(name)
                          ? QuerySet::RoomSubsets
                          : QuerySet::AllCells};
}

// --model FILE: measures a saved model on its case (no training), e.g. to compare inference
// options on one trained policy. --model generalist: the built-in generalist on every case
// (no per-plan training at all).
int measureSavedModel(const Options& o) {
    const bool builtIn = o.model == "generalist";
    std::shared_ptr<const DqnModel> model;
    if (builtIn) {
        const double before = threadCpuSeconds();
        model = generalistModel();
        std::fprintf(stderr, "generalist loaded in %.3f s: %s\n", threadCpuSeconds() - before,
                     model->info.provenance.c_str());
    } else {
        model = std::make_shared<DqnModel>(loadDqnModelFile(o.model));
    }
    const bool generalist = model->info.generalist;
    if (o.cases.size() != 1 && !generalist)
        throw std::invalid_argument("--model needs exactly one case (--cases NAME)");
    for (const std::string& name : o.cases) {
        const Project project = loadCase(name, o.seed);
        const PreparedPlan prepared = preparePlan(project.plan, project.robot,
                                                  generalist ? 90.0 : model->info.stripeAngleDeg);
        checkModelFitsGraph(model->info, prepared.graph, o.model);
        const OrderRefinement refinement =
            o.refinement.empty() ? model->info.refinement : refinementFromName(o.refinement);
        const FinalFigures f = measure(*model->agent, prepared.graph, model->info.environment,
                                       refinement, caseOf(name), o.queries, o.seed);
        printRow(name,
                 generalist ? (builtIn ? "generalist (built in)" : "generalist (" + o.model + ")")
                            : model->info.setting + " (saved)",
                 model->info.episodes, model->info.steps, f);
    }
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    Options o;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string key = argv[i], value = argv[i + 1];
        if (key == "--seconds")
            o.seconds = std::stod(value);
        else if (key == "--seed")
            o.seed = std::stoull(value);
        else if (key == "--queries")
            o.queries = std::stoi(value);
        else if (key == "--cases")
            o.cases = splitList(value);
        else if (key == "--settings")
            o.settings = splitList(value);
        else if (key == "--out")
            o.out = value;
        else if (key == "--model")
            o.model = value;
        else if (key == "--refine")
            o.refinement = value;
        else {
            std::cerr << "unknown option " << key << "\n";
            return 2;
        }
    }
    std::printf("| plan | setting | episodes | env steps | gap (policy) | max gap | gap (dqn "
                "solver) | max | greedy gap | greedy refined | beam 4 | beam 4 refined | failures "
                "| reference | ms/query (max) | beam ms |\n");
    std::printf("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|\n");
    if (!o.model.empty())
        return measureSavedModel(o);
    std::error_code created; // the curves and models go there; a missing folder is made
    std::filesystem::create_directories(o.out, created);
    if (created) {
        std::cerr << o.out << ": cannot create the folder (" << created.message() << ")\n";
        return 2;
    }
    for (const std::string& name : o.cases) {
        const Project project = loadCase(name, o.seed);
        const Case c = caseOf(name);
        const PreparedPlan prepared = preparePlan(project.plan, project.robot, 90.0);
        for (const std::string& setting : o.settings) {
            const TrainingOptions options = settingOptions(setting, o.seed);
            DqnTrainer trainer(prepared.graph, options, 90.0, project.robot.coverageWidth);
            std::ofstream csv(o.out + "/curves-" + name + "-" + setting + ".csv");
            csv << "episode,seconds,reward,moving_average,loss,epsilon,gap,refined_gap\n";
            const double evaluationEvery = o.seconds / 20.0;
            double nextEvaluation = 0.0;
            const double cpuStart = threadCpuSeconds();
            double evaluationCpu = 0.0; // not counted as training time
            auto trainingCpu = [&] { return threadCpuSeconds() - cpuStart - evaluationCpu; };
            // demos=N: N expert walks of the plan, then pretrain=STEPS gradient steps on them
            // alone (DQfD), all within the CPU budget.
            const long demos = settingValue(setting, "demos", 0);
            if (demos > 0) {
                const long added = trainer.addDemonstrations(static_cast<int>(demos));
                const double loss = trainer.pretrain(settingValue(setting, "pretrain", 0));
                std::fprintf(stderr,
                             "%s %s: %ld expert transitions, pre-training loss %.4f, %.1f s\n",
                             name.c_str(), setting.c_str(), added, loss, trainingCpu());
            }
            trainer.train(
                0, 0.0,
                [&](const TrainingProgress& p) {
                    const double cpu = trainingCpu();
                    csv << p.episode << ',' << cpu << ',' << p.reward << ',' << p.movingAverage
                        << ',' << (std::isnan(p.loss) ? 0.0 : p.loss) << ',' << p.epsilon;
                    if (cpu >= nextEvaluation) {
                        const double before = threadCpuSeconds();
                        const EvaluationReport r = trainer.evaluate();
                        evaluationCpu += threadCpuSeconds() - before;
                        csv << ',' << r.meanGap << ',' << r.meanRefinedGap;
                        nextEvaluation += evaluationEvery;
                    } else {
                        csv << ",,";
                    }
                    csv << '\n';
                },
                [&] { return trainingCpu() >= o.seconds; });
            const EvaluationReport last = trainer.evaluate();
            csv << trainer.episodes() << ',' << o.seconds << ",,,,," << last.meanGap << ','
                << last.meanRefinedGap << '\n';
            // best=1: measure the best evaluated weights, as `train` and the dock keep them.
            if (setting.find("+best=1") != std::string::npos && trainer.restoreBestEvaluated())
                std::fprintf(stderr, "%s %s: measuring the weights of episode %ld\n", name.c_str(),
                             setting.c_str(), trainer.bestEvaluatedEpisode());
            const FinalFigures f =
                measure(trainer.agent(), prepared.graph, trainer.options().environment,
                        trainer.options().refinement, c, o.queries, o.seed);
            printRow(name, setting, trainer.episodes(), trainer.agent().stepCount(), f);
            std::fflush(stdout);
            trainer.save(o.out + "/model-" + name + "-" + setting + ".fcdqn");
        }
    }
    return 0;
}

// floorcover-cli train: trains the Double-DQN planner for one plan and saves the model.
// Ctrl-C stops after the current episode and saves; a second Ctrl-C aborts.
#include "CliCommon.h"
#include "learning/dqn/DqnTrainer.h"
#include "learning/dqn/GeneralistModel.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>

namespace fc::cli {
namespace {

volatile std::sig_atomic_t interrupted = 0;

void onInterrupt(int) {
    interrupted = 1;
    std::signal(SIGINT, SIG_DFL); // a second Ctrl-C ends the process
}

void printProgress(const TrainingProgress& p) {
    std::printf("episode %6ld  steps %8ld  reward %8.3f  average %8.3f  loss %9.5f  "
                "epsilon %5.3f  steps/s %6.0f",
                p.episode, p.totalSteps, p.reward, p.movingAverage,
                std::isnan(p.loss) ? 0.0 : p.loss, p.epsilon, p.stepsPerSecond);
    if (p.evaluation)
        std::printf("  gap %6.2f%%  refined %6.2f%% (vs %s, %d queries, %.1f ms each)",
                    100.0 * p.evaluation->meanGap, 100.0 * p.evaluation->meanRefinedGap,
                    p.evaluation->reference.c_str(), p.evaluation->queries,
                    p.evaluation->meanMilliseconds);
    std::printf("\n");
    std::fflush(stdout);
}

const char* stopName(TrainingStop stop) {
    switch (stop) {
    case TrainingStop::EpisodeLimit:
        return "episodes";
    case TrainingStop::TimeLimit:
        return "seconds";
    case TrainingStop::Cancelled:
        return "interrupted";
    }
    return "";
}

} // namespace

int commandTrain(const Arguments& args) {
    args.allowOnly({"--out", "--episodes", "--seconds", "--seed", "--setting", "--resume",
                    "--evaluate-every", "--width", "--robot-diameter", "--cleaning-diameter",
                    "--angle", "--no-transition-cells", "--from-scratch", "--building"});
    const std::string& path = planPath(args);
    const auto out = args.text("--out");
    if (!out)
        throw InputError("train needs --out MODEL");
    const long episodes = static_cast<long>(args.integer("--episodes").value_or(0));
    double seconds = args.number("--seconds").value_or(0.0);
    if (episodes < 0 || seconds < 0.0 || !std::isfinite(seconds))
        throw InputError("--episodes and --seconds must not be negative");
    // 0 used to read as "not given" and trained for the default 300 s.
    if ((args.has("--episodes") && episodes == 0) || (args.has("--seconds") && seconds == 0.0))
        throw InputError("--episodes and --seconds must be positive (leave both out for 300 s)");
    if (episodes == 0 && seconds == 0.0)
        seconds = 300.0;
    const auto seed = static_cast<std::uint64_t>(args.integer("--seed").value_or(1));
    const std::string setting = args.text("--setting").value_or("graph");
    if (setting != "improved" && setting != "paper" && setting != "graph")
        throw InputError("--setting must be graph, improved or paper");

    const Project project = loadProject(path, args);
    PreparedPlan prepared;
    double angle = 90.0;
    try {
        PlanRequest request = requestFrom(project, args);
        angle = request.sweep.angleDeg;
        if (request.sweep.automatic) {
            request.solver = "heuristic"; // the angle the planner would choose
            angle = planCoverage(request).stripeAngleDeg;
        }
        prepared = preparePlan(request.plan, request.robot, angle, request.transitionCells);
    } catch (const InputError& e) {
        rethrowInFile(path, e);
    } catch (const SolverError& e) {
        throw InputError(path + ": " + e.what());
    }

    std::unique_ptr<DqnTrainer> trainer;
    if (args.has("--resume") && std::filesystem::exists(*out)) {
        trainer = std::make_unique<DqnTrainer>(prepared.graph, loadDqnModelFile(*out), *out);
        std::cout << "resuming " << *out << " after " << trainer->episodes() << " episodes\n";
    } else {
        TrainingOptions options = TrainingOptions::named(setting, seed);
        options.evaluationInterval = static_cast<int>(args.integer("--evaluate-every").value_or(0));
        // The graph setting fine-tunes the generalist unless told otherwise; the image
        // settings have no generalist (their network is tied to one graph's size).
        if (setting == "graph" && !args.has("--from-scratch")) {
            options.initialModel = generalistModel();
            std::cout << "starting from " << kGeneralistModelName << " (--from-scratch to "
                      << "start from random weights)\n";
        }
        trainer = std::make_unique<DqnTrainer>(prepared.graph, options, angle,
                                               prepared.robot.coverageWidth);
    }
    if (auto every = args.integer("--evaluate-every"); every && args.has("--resume"))
        std::cerr << "floorcover-cli: note: --evaluate-every is ignored when resuming\n";
    std::cout << "training " << trainer->options().setting << " DQN on " << path << ": "
              << prepared.graph.nodes.size() << " corners, " << prepared.graph.cells.size()
              << " cells, sweep angle " << angle << " deg\n";

    if (trainer->episodes() == 0 && !args.has("--from-scratch") && setting == "graph") {
        // Where fine-tuning starts: the generalist on this plan's evaluation queries (also a
        // candidate for the model kept at the end).
        const EvaluationReport start = trainer->evaluate();
        std::printf("the generalist on this plan: policy alone %.2f%% above the reference, "
                    "refined %.2f%% (%d queries)\n",
                    100.0 * start.meanGap, 100.0 * start.meanRefinedGap, start.queries);
    }
    interrupted = 0;
    std::signal(SIGINT, onInterrupt);
    auto lastPrint = std::chrono::steady_clock::now() - std::chrono::seconds(10);
    const TrainingStop stop = trainer->train(
        episodes, seconds,
        [&](const TrainingProgress& p) {
            const auto now = std::chrono::steady_clock::now();
            if (p.evaluation || now - lastPrint >= std::chrono::seconds(1)) {
                printProgress(p);
                lastPrint = now;
            }
        },
        [] { return interrupted != 0; });
    std::signal(SIGINT, SIG_DFL);

    trainer->save(*out); // first: a second Ctrl-C during the evaluation loses nothing
    // The last weights are evaluated too; the best evaluated ones are what is kept.
    EvaluationReport report = trainer->evaluate();
    const double lastGap = report.meanGap;
    if (trainer->restoreBestEvaluated()) {
        report = *trainer->bestEvaluation();
        std::cout << "keeping the weights of episode " << trainer->bestEvaluatedEpisode()
                  << " (policy alone " << 100.0 * report.meanGap << "% above the reference; "
                  << "the last weights: " << 100.0 * lastGap << "%)\n";
        trainer->save(*out);
    }
    const DqnModelInfo info = trainer->modelInfo();
    std::printf("{\"model\":\"%s\",\"stopped_by\":\"%s\",\"episodes\":%ld,\"steps\":%ld,"
                "\"seconds\":%.1f,\"gap\":%.5f,\"refined_gap\":%.5f,\"reference\":\"%s\","
                "\"queries\":%d,\"failures\":%d,\"kept_episode\":%ld}\n",
                out->c_str(), stopName(stop), info.episodes, info.steps, info.trainingSeconds,
                report.meanGap, report.meanRefinedGap, report.reference.c_str(), report.queries,
                report.failures, trainer->bestEvaluatedEpisode());
    return 0;
}

} // namespace fc::cli

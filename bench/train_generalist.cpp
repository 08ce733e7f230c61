// floorcover-train-generalist: trains the generalist Double-DQN model (issue 17, item 1), one
// graph-state policy for every floor plan, on seeded generated floors only (never the sample
// plans): rotated offices, rooms behind doors of random width, slanted rooms, star rooms with
// round pillars, pillar halls, office floors of 4-16 rooms and halls with obstacles. Each
// episode draws one floor, a random start and end and a random set of cells still to cover.
//   floorcover-train-generalist [--floors N] [--episodes N | --seconds S] [--seed N]
//                               [--evaluate-every N] [--hidden N] [--lr R] [--small-rooms]
//                               --out FILE
//   floorcover-train-generalist --validate MODEL [--seed N]   (its gap on the held-out floors)
// One thread; with --episodes the model is the same bit for bit on every run. Every
// --evaluate-every episodes the policy alone is measured on 12 held-out generated floors
// (another seed, 4 queries each) and the best model so far is the one saved.
#include "PlanGenerator.h"
#include "learning/dqn/DqnModelFile.h"
#include "learning/dqn/DqnPolicy.h"
#include "learning/dqn/DqnTrainer.h"
#include "model/SyntheticPlans.h"
#include "pipeline/Planner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <random>
#include <string>
#include <vector>

using namespace fc;

namespace {

struct Options {
    int floors = 60;
    long episodes = 0;
    double seconds = 0.0;
    std::uint64_t seed = 1;
    int evaluateEvery = 0;
    int hidden = 0;            // 0: the graph setting's
    int messageRounds = -1;    // < 0: the graph setting's
    int neighbours = 0;        // 0: the agent's default
    double learningRate = 0.0; // 0: the graph setting's
    int demonstrations = 0;    // expert walks per floor (DQfD)
    long pretrainSteps = 0;    // gradient steps on them before the first episode
    double margin = -1.0;      // < 0: the agent's default
    double demonstrationShare = -1.0;
    double marginWeight = -1.0;
    bool smallRooms = false; // also rooms of 8-20 m with 1-3 obstacles
    std::string out;
    std::string validate; // measure this model on the validation floors and stop
};

// Floors larger than this slow every gradient step and add little: the state is per corner.
constexpr std::size_t kMaxTrainingCorners = 400;

Ring box(double x0, double y0, double x1, double y1) {
    return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// A single room of 8-20 m by 6-14 m with 1-3 boxes at least 1.5 m from the walls and from
// each other: the floors of a few cells that the other kinds lack (a hall there is 16-40 m
// with 3-8 obstacles), where the generalist's policy alone was 19-69% above the optimum.
Plan smallRoom(std::uint64_t seed, std::string& name) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Plan plan;
    const double width = 8.0 + 12.0 * unit(rng), height = 6.0 + 8.0 * unit(rng);
    const int wanted = 1 + static_cast<int>(rng() % 3);
    plan.boundary = box(0, 0, width, height);
    std::vector<BoundingBox> placed;
    for (int attempt = 0; static_cast<int>(placed.size()) < wanted && attempt < 200; ++attempt) {
        const double w = 1.0 + unit(rng) * 0.4 * width, h = 1.0 + unit(rng) * 0.4 * height;
        const double x = 1.5 + unit(rng) * (width - w - 3.0);
        const double y = 1.5 + unit(rng) * (height - h - 3.0);
        BoundingBox b;
        b.add({x, y});
        b.add({x + w, y + h});
        bool clear = true;
        for (const BoundingBox& o : placed)
            clear = clear && !(b.minX < o.maxX + 1.5 && o.minX < b.maxX + 1.5 &&
                               b.minY < o.maxY + 1.5 && o.minY < b.maxY + 1.5);
        if (!clear)
            continue;
        placed.push_back(b);
        plan.obstacles.push_back(box(x, y, x + w, y + h));
    }
    char text[96];
    std::snprintf(text, sizeof text, "room %.1f x %.1f m with %zu obstacles, seed %llu", width,
                  height, placed.size(), static_cast<unsigned long long>(seed));
    name = text;
    return plan;
}

Plan trainingPlan(int index, std::uint64_t seed, bool smallRooms, std::string& name) {
    const std::uint64_t s = seed * 1000003ULL + static_cast<std::uint64_t>(index);
    const std::vector<fcgen::Family> families = fcgen::allFamilies();
    const int kinds = static_cast<int>(families.size()) + (smallRooms ? 3 : 2);
    const int kind = index % kinds;
    if (smallRooms && kind == kinds - 1)
        return smallRoom(s, name);
    const int last = static_cast<int>(families.size()) + 2; // the kinds without small rooms
    if (kind < static_cast<int>(families.size())) {
        const fcgen::GeneratedPlan g =
            fcgen::generatePlan(families[static_cast<std::size_t>(kind)], s);
        name = g.description;
        return g.plan;
    }
    if (kind == last - 2) {
        const int rooms = 4 + index % 13;
        name = "office floor of " + std::to_string(rooms) + " rooms, seed " + std::to_string(s);
        return generateOfficeFloor(rooms, s);
    }
    const double width = 16.0 + static_cast<double>(index % 5) * 6.0;
    const int obstacles = 3 + index % 6;
    name = "hall " + std::to_string(static_cast<int>(width)) + " m with " +
           std::to_string(obstacles) + " obstacles, seed " + std::to_string(s);
    return generateHallWithObstacles(width, width * 0.7, obstacles, s);
}

// Share of the expert transitions whose expert corner the policy ranks first, and whose
// expert cell it picks (any corner of it).
void printImitation(const DqnAgent& agent) {
    const ReplayMemory& demos = agent.demonstrations();
    const auto channels = static_cast<std::size_t>(agent.parameters().inputChannels);
    long corner = 0, total = 0, greedy = 0, top3 = 0, twins = 0;
    for (std::size_t i = 0; i < demos.size(); i += 7) {
        const Transition& t = demos.at(i);
        const std::vector<float> q = agent.qValues(t.observation, 1);
        int best = -1, better = 0;
        for (std::size_t c = 0; c < q.size(); ++c) {
            if (t.observation[c * channels] < 0.5f)
                continue;
            if (best < 0 || q[c] > q[static_cast<std::size_t>(best)])
                best = static_cast<int>(c);
            better += q[c] > q[static_cast<std::size_t>(t.action)] ? 1 : 0;
        }
        corner += best == t.action ? 1 : 0;
        if (best != t.action && best >= 0) {
            bool same = true;
            for (std::size_t f = 1; f < channels; ++f)
                same = same &&
                       std::abs(t.observation[static_cast<std::size_t>(best) * channels + f] -
                                t.observation[static_cast<std::size_t>(t.action) * channels + f]) <
                           1e-4f;
            twins += same ? 1 : 0;
        }
        top3 += better < 3 ? 1 : 0;
        greedy += t.observation[static_cast<std::size_t>(t.action) * channels + 15] > 0.5f ? 1 : 0;
        ++total;
    }
    const double n = std::max<double>(1.0, static_cast<double>(total));
    std::fprintf(stderr, "misses where the chosen corner's features equal the expert's: %ld\n",
                 twins);
    std::fprintf(stderr,
                 "imitation: expert corner first in %.1f%% of %ld states, in the first three in "
                 "%.1f%%; the expert takes a cheapest corner in %.1f%%\n",
                 100.0 * static_cast<double>(corner) / n, total,
                 100.0 * static_cast<double>(top3) / n, 100.0 * static_cast<double>(greedy) / n);
}

// `count` floors drawn from `seed` (training: the run's seed; validation: another one).
std::vector<CornerGraph> generatedFloors(int count, std::uint64_t seed, bool smallRooms) {
    std::vector<CornerGraph> floors;
    const RobotProfile robot;
    for (int i = 0; static_cast<int>(floors.size()) < count && i < 10 * count; ++i) {
        std::string name;
        try {
            const Plan plan = trainingPlan(i, seed, smallRooms, name);
            const std::vector<double> angles = candidateAngles(plan);
            PreparedPlan prepared = preparePlan(plan, robot, angles.empty() ? 90.0 : angles[0]);
            const std::size_t corners = prepared.graph.nodes.size();
            if (corners > kMaxTrainingCorners || prepared.graph.cells.size() < 2) {
                std::fprintf(stderr, "skipped (%zu corners): %s\n", corners, name.c_str());
                continue;
            }
            std::fprintf(stderr, "floor %zu: %zu corners, %zu cells: %s\n", floors.size(), corners,
                         prepared.graph.cells.size(), name.c_str());
            floors.push_back(std::move(prepared.graph));
        } catch (const std::exception& e) {
            std::fprintf(stderr, "skipped (%s): %s\n", e.what(), name.c_str());
        }
    }
    return floors;
}

std::string argumentText(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

// Held-out floors and their reference costs (exact up to 12 cells, else heuristic).
class Validation {
public:
    Validation(std::vector<CornerGraph> floors, std::uint64_t seed) : floors_(std::move(floors)) {
        for (std::size_t f = 0; f < floors_.size(); ++f) {
            const CornerGraph& g = floors_[f];
            const QuerySet kind = roomCount(g) > 1 ? QuerySet::RoomSubsets : QuerySet::AllCells;
            for (const Query& q : randomQueries(g, 4, seed * 31 + f, kind)) {
                const long cells = std::count(q.required.begin(), q.required.end(), 1);
                queries_.push_back(
                    {f, q,
                     cells <= 12 ? solveExact(g, q).graphCost : solveHeuristic(g, q).graphCost});
            }
        }
    }
    // Mean of the policy alone's cost / reference - 1.
    double policyGap(const DqnAgent& agent, const EnvironmentOptions& environment) const {
        double sum = 0.0;
        for (const Item& item : queries_) {
            const Solution s = solveWithPolicy(agent, floors_[item.floor], item.query, environment);
            sum += s.graphCost / std::max(item.reference, 1e-9) - 1.0;
        }
        return queries_.empty() ? 0.0 : sum / static_cast<double>(queries_.size());
    }

private:
    struct Item {
        std::size_t floor;
        Query query;
        double reference;
    };
    std::vector<CornerGraph> floors_;
    std::vector<Item> queries_;
};

bool parse(int argc, char** argv, Options& o) {
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const bool hasValue = i + 1 < argc;
        if (arg == "--floors" && hasValue)
            o.floors = std::atoi(argv[++i]);
        else if (arg == "--episodes" && hasValue)
            o.episodes = std::atol(argv[++i]);
        else if (arg == "--seconds" && hasValue)
            o.seconds = std::atof(argv[++i]);
        else if (arg == "--seed" && hasValue)
            o.seed = std::strtoull(argv[++i], nullptr, 10);
        else if (arg == "--evaluate-every" && hasValue)
            o.evaluateEvery = std::atoi(argv[++i]);
        else if (arg == "--hidden" && hasValue)
            o.hidden = std::atoi(argv[++i]);
        else if (arg == "--messages" && hasValue)
            o.messageRounds = std::atoi(argv[++i]);
        else if (arg == "--neighbours" && hasValue)
            o.neighbours = std::atoi(argv[++i]);
        else if (arg == "--lr" && hasValue)
            o.learningRate = std::atof(argv[++i]);
        else if (arg == "--demos" && hasValue)
            o.demonstrations = std::atoi(argv[++i]);
        else if (arg == "--pretrain" && hasValue)
            o.pretrainSteps = std::atol(argv[++i]);
        else if (arg == "--margin" && hasValue)
            o.margin = std::atof(argv[++i]);
        else if (arg == "--margin-weight" && hasValue)
            o.marginWeight = std::atof(argv[++i]);
        else if (arg == "--demo-share" && hasValue)
            o.demonstrationShare = std::atof(argv[++i]);
        else if (arg == "--validate" && hasValue)
            o.validate = argv[++i];
        else if (arg == "--small-rooms")
            o.smallRooms = true;
        else if (arg == "--out" && hasValue)
            o.out = argv[++i];
        else
            return false;
    }
    if (!o.validate.empty())
        return true;
    return !o.out.empty() && o.floors > 0 &&
           (o.episodes > 0 || o.seconds > 0.0 || o.pretrainSteps > 0);
}

} // namespace

int main(int argc, char** argv) {
    Options o;
    if (!parse(argc, argv, o)) {
        std::cerr
            << "usage: floorcover-train-generalist [--floors N] [--episodes N | --seconds "
               "S] [--seed N] [--evaluate-every N] [--hidden N] [--messages N] [--neighbours "
               "K] [--lr R] [--demos N "
               "[--pretrain STEPS] [--margin M] [--demo-share F]] [--small-rooms] --out FILE\n";
        return 2;
    }
    if (!o.validate.empty()) {
        const DqnModel model = loadDqnModelFile(o.validate);
        const Validation validation(generatedFloors(12, o.seed + 7777, o.smallRooms), o.seed);
        std::printf("%s: policy alone %.2f%% above the reference on the validation floors\n",
                    o.validate.c_str(),
                    100.0 * validation.policyGap(*model.agent, model.info.environment));
        return 0;
    }
    std::vector<CornerGraph> floors = generatedFloors(o.floors, o.seed, o.smallRooms);
    // Model selection on floors it never trains on (another seed): the policy alone is
    // measured there at every evaluation, and the best model so far is what is saved.
    const Validation validation(generatedFloors(12, o.seed + 7777, o.smallRooms), o.seed);
    if (floors.empty()) {
        std::cerr << "no training floor could be prepared\n";
        return 1;
    }
    TrainingOptions options = TrainingOptions::graph(o.seed);
    options.evaluationInterval = o.evaluateEvery;
    options.evaluationQueries = 40;
    // Many floors: a longer memory and exploration schedule than one plan's.
    options.agent.replayCapacity = 20'000;
    options.agent.epsilonDecaySteps = 30'000;
    if (o.hidden > 0)
        options.agent.hiddenUnits = o.hidden;
    if (o.messageRounds >= 0)
        options.agent.messageRounds = o.messageRounds;
    if (o.neighbours > 0)
        options.agent.messageNeighbours = o.neighbours;
    if (o.learningRate > 0.0)
        options.agent.learningRate = o.learningRate;
    if (o.margin >= 0.0)
        options.agent.margin = o.margin;
    if (o.demonstrationShare >= 0.0)
        options.agent.demonstrationShare = o.demonstrationShare;
    if (o.marginWeight >= 0.0)
        options.agent.marginWeight = o.marginWeight;
    if (o.demonstrations > 0)
        options.agent.demonstrationCapacity = std::max(20'000, o.demonstrations * o.floors * 40);
    std::string provenance = "floorcover-train-generalist --floors " + std::to_string(o.floors) +
                             " --seed " + std::to_string(o.seed);
    provenance += o.episodes > 0 ? " --episodes " + std::to_string(o.episodes)
                                 : " --seconds " + std::to_string(o.seconds);
    if (o.hidden > 0)
        provenance += " --hidden " + std::to_string(o.hidden);
    if (o.messageRounds >= 0)
        provenance += " --messages " + std::to_string(o.messageRounds);
    if (o.neighbours > 0)
        provenance += " --neighbours " + std::to_string(o.neighbours);
    if (o.learningRate > 0.0)
        provenance += " --lr " + argumentText(o.learningRate);
    if (o.demonstrations > 0)
        provenance += " --demos " + std::to_string(o.demonstrations) + " --pretrain " +
                      std::to_string(o.pretrainSteps);
    if (o.margin >= 0.0)
        provenance += " --margin " + argumentText(o.margin);
    if (o.demonstrationShare >= 0.0)
        provenance += " --demo-share " + argumentText(o.demonstrationShare);
    if (o.marginWeight >= 0.0)
        provenance += " --margin-weight " + argumentText(o.marginWeight);
    if (o.smallRooms)
        provenance += " --small-rooms";
    DqnTrainer trainer(std::move(floors), options, RobotProfile{}.coverageWidth, provenance);
    const auto start = std::chrono::steady_clock::now();
    long shown = 0;
    double bestGap = validation.policyGap(trainer.agent(), trainer.options().environment);
    long bestEpisode = 0;
    trainer.save(o.out);
    if (o.demonstrations > 0) {
        printImitation(trainer.agent());
        const long added = trainer.addDemonstrations(o.demonstrations);
        std::fprintf(
            stderr, "%ld expert transitions (%d walks per floor) after %.0f s\n", added,
            o.demonstrations,
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        // Pre-training in rounds, each measured on the validation floors.
        const long round = 1000;
        for (long done = 0; done < o.pretrainSteps; done += round) {
            const double loss = trainer.pretrain(std::min(round, o.pretrainSteps - done));
            const double gap = validation.policyGap(trainer.agent(), trainer.options().environment);
            const bool better = gap < bestGap;
            if (better) {
                bestGap = gap;
                trainer.save(o.out);
            }
            std::fprintf(
                stderr,
                "pre-training step %ld  %.0f s  loss %.4f (margin %.4f)  %.2f%% on the validation "
                "floors%s\n",
                std::min(done + round, o.pretrainSteps),
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                loss, trainer.agent().lastMarginLoss(), 100.0 * gap,
                better ? " (best: saved)" : "");
            printImitation(trainer.agent());
        }
    }
    if (o.episodes > 0 || o.seconds > 0.0)
        trainer.train(o.episodes, o.episodes > 0 ? 0.0 : o.seconds, [&](const TrainingProgress& p) {
            if (p.evaluation) {
                const double gap =
                    validation.policyGap(trainer.agent(), trainer.options().environment);
                const bool better = gap < bestGap;
                if (better) {
                    bestGap = gap;
                    bestEpisode = p.episode;
                    trainer.save(o.out);
                }
                std::fprintf(
                    stderr,
                    "episode %ld  %.0f s  policy gap %.2f%% (refined %.2f%%) on its floors, "
                    "%.2f%% on the validation floors%s\n",
                    p.episode, p.elapsedSeconds, 100.0 * p.evaluation->meanGap,
                    100.0 * p.evaluation->meanRefinedGap, 100.0 * gap,
                    better ? " (best: saved)" : "");
            }
            if (p.episode - shown >= 500) {
                shown = p.episode;
                std::fprintf(
                    stderr, "episode %ld  %.0f s  reward (avg) %.3f  epsilon %.2f  %.0f steps/s\n",
                    p.episode, p.elapsedSeconds, p.movingAverage, p.epsilon, p.stepsPerSecond);
            }
        });
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double lastGap = validation.policyGap(trainer.agent(), trainer.options().environment);
    if (lastGap < bestGap || (o.evaluateEvery <= 0 && o.pretrainSteps <= 0)) {
        bestGap = lastGap;
        bestEpisode = trainer.episodes();
        trainer.save(o.out);
    }
    std::printf("trained %ld episodes in %.0f s on %d floors; saved %s, the model after %ld "
                "episodes: policy alone %.2f%% above the reference on the validation floors\n",
                trainer.episodes(), seconds, o.floors, o.out.c_str(), bestEpisode, 100.0 * bestGap);
    return 0;
}

// floorcover-property-bench: many random plans of the property generator (tests/checker)
// through planning and the independent checker; prints the failure rate per family and the
// worst cases, as Markdown.
//   floorcover-property-bench [--count N] [--seed S] [--family NAME] [--worst K] [--write DIR]
//                             [--no-rings]
// (--write DIR: each generated plan is also written there as FAMILY-SEED.geojson, to plan it
// again with floorcover-cli)
// Plan i (0-based) is family i mod F (F families, or the one named) with seed S + i / F, so
// a failure is reproduced by property_tests' generator with that family and seed.
#include "PlanGenerator.h"
#include "PropertyCheck.h"
#include "formats/FileIO.h"
#include "formats/PlanIO.h"
#include "learning/dqn/DqnSolver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

using namespace fcgen;

namespace {

struct Result {
    GeneratedPlan plan;
    Outcome outcome;
    std::string generatorError;
};

struct Tally {
    int runs = 0, failed = 0, collision = 0, coverage = 0, crash = 0, slow = 0, inputError = 0;
    double coverageSum = 0.0, worstCoverage = 1.0, worstClearance = INFINITY, seconds = 0.0;
    int planned = 0;
};

void usage() {
    std::fprintf(stderr,
                 "usage: floorcover-property-bench [--count N] [--seed S] "
                 "[--family NAME] [--worst K] [--solver NAME] [--write DIR] [--no-rings]\n");
}

} // namespace

int main(int argc, char** argv) {
    int count = 100, worst = 10;
    std::uint64_t seed = 1;
    std::vector<Family> families = allFamilies();
    std::string solver = "heuristic";
    bool rings = true;
    std::string writeDir;
    fc::registerDqnSolver(); // solver dqn: the built-in generalist model
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--no-rings") { // A/B runs: stripes and wall loops only
            rings = false;
            continue;
        }
        if (i + 1 >= argc) {
            usage();
            return 2;
        }
        const std::string value = argv[++i];
        if (arg == "--count")
            count = std::max(1, std::atoi(value.c_str()));
        else if (arg == "--seed")
            seed = std::strtoull(value.c_str(), nullptr, 10);
        else if (arg == "--solver")
            solver = value;
        else if (arg == "--write")
            writeDir = value;
        else if (arg == "--worst")
            worst = std::max(0, std::atoi(value.c_str()));
        else if (arg == "--family") {
            families.clear();
            for (Family f : allFamilies())
                if (value == familyName(f))
                    families.push_back(f);
            if (families.empty()) {
                std::fprintf(stderr, "unknown family %s\n", value.c_str());
                return 2;
            }
        } else {
            usage();
            return 2;
        }
    }

    if (!writeDir.empty()) {
        std::error_code made;
        std::filesystem::create_directories(writeDir, made);
        if (made) {
            std::fprintf(stderr, "--write %s: %s\n", writeDir.c_str(), made.message().c_str());
            return 2;
        }
    }
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<Result> results;
    std::map<std::string, Tally> tallies;
    for (int i = 0; i < count; ++i) {
        const Family family = families[static_cast<std::size_t>(i) % families.size()];
        const std::uint64_t caseSeed = seed + static_cast<std::uint64_t>(i) / families.size();
        Result r;
        try {
            r.plan = generatePlan(family, caseSeed);
        } catch (const std::exception& e) {
            r.plan.family = family;
            r.plan.seed = caseSeed;
            r.generatorError = e.what();
        }
        if (r.generatorError.empty() && !writeDir.empty())
            fc::writeFileAtomically(writeDir + "/" + familyName(family) + "-" +
                                        std::to_string(caseSeed) + ".geojson",
                                    fc::writeGeoJsonPlan(r.plan.plan));
        if (r.generatorError.empty()) {
            fc::PlanRequest request = defaultRequest(r.plan.plan);
            request.solver = solver;
            request.rings = rings;
            r.outcome = planAndCheck(request);
        }
        Tally& t = tallies[familyName(family)];
        ++t.runs;
        const Outcome& o = r.outcome;
        if (!r.generatorError.empty() || !o.passed())
            ++t.failed;
        if (!r.generatorError.empty() || o.otherError)
            ++t.crash;
        t.inputError += o.inputError;
        if (o.planned) {
            ++t.planned;
            t.collision += !o.collisionFree;
            t.coverage += !(o.covers || o.reportsLoss);
            t.slow += !o.inTime;
            t.coverageSum += o.check.coverage;
            t.worstCoverage = std::min(t.worstCoverage, o.check.coverage);
            t.worstClearance = std::min(t.worstClearance, o.check.clearance.minimum);
        }
        t.seconds += o.seconds + o.checkSeconds;
        std::fprintf(stderr, "[%d/%d] %s: %s%s\n", i + 1, count,
                     r.generatorError.empty() ? r.plan.description.c_str() : familyName(family),
                     r.generatorError.empty() ? o.summary().c_str() : r.generatorError.c_str(),
                     r.generatorError.empty() && o.passed() ? "" : "  FAILED");
        results.push_back(std::move(r));
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    std::printf("# Property bench: %d random plans, seed %llu\n\n", count,
                static_cast<unsigned long long>(seed));
    std::printf("W = 1 m, L = 0.6 m, solver `%s`, default sweep. A run fails on (a) a "
                "clearance below L/2 − 0.6 mm or a waypoint outside the free space, (b) "
                "coverage below 99.5%% of the checker's sweepable area without the planner's "
                "`uncoveredArea` within 0.2%% of the floor of the checker's, (c) an exception "
                "other than `fc::InputError`, or planning longer than %.0f s. %.1f s in all.\n\n",
                solver.c_str(), kSecondsPerPlan, seconds);
    std::printf("| family | runs | failed | failure rate | (a) collision | (b) coverage | (c) "
                "crash | (c) slow | input errors | mean coverage | worst coverage | smallest "
                "clearance m | mean s |\n");
    std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    Tally all;
    for (const auto& [name, t] : tallies) {
        std::printf("| %s | %d | %d | %.1f%% | %d | %d | %d | %d | %d | %.2f%% | %.2f%% | %.3f | "
                    "%.2f |\n",
                    name.c_str(), t.runs, t.failed, 100.0 * t.failed / t.runs, t.collision,
                    t.coverage, t.crash, t.slow, t.inputError,
                    t.planned ? 100.0 * t.coverageSum / t.planned : 0.0, 100.0 * t.worstCoverage,
                    t.worstClearance, t.seconds / t.runs);
        all.runs += t.runs, all.failed += t.failed, all.collision += t.collision;
        all.coverage += t.coverage, all.crash += t.crash, all.slow += t.slow;
        all.inputError += t.inputError, all.planned += t.planned;
        all.coverageSum += t.coverageSum, all.seconds += t.seconds;
        all.worstCoverage = std::min(all.worstCoverage, t.worstCoverage);
        all.worstClearance = std::min(all.worstClearance, t.worstClearance);
    }
    std::printf("| **all** | %d | %d | %.1f%% | %d | %d | %d | %d | %d | %.2f%% | %.2f%% | %.3f | "
                "%.2f |\n\n",
                all.runs, all.failed, 100.0 * all.failed / all.runs, all.collision, all.coverage,
                all.crash, all.slow, all.inputError,
                all.planned ? 100.0 * all.coverageSum / all.planned : 0.0,
                100.0 * all.worstCoverage, all.worstClearance, all.seconds / all.runs);

    auto printWorst = [&](const char* title, auto key, auto keep) {
        std::vector<const Result*> picked;
        for (const Result& r : results)
            if (keep(r))
                picked.push_back(&r);
        std::sort(picked.begin(), picked.end(),
                  [&](const Result* a, const Result* b) { return key(*a) < key(*b); });
        if (static_cast<int>(picked.size()) > worst)
            picked.resize(static_cast<std::size_t>(worst));
        std::printf("## %s\n\n", title);
        if (picked.empty())
            std::printf("- none\n");
        for (const Result* r : picked)
            std::printf("- %s: %s\n",
                        r->generatorError.empty() ? r->plan.description.c_str()
                                                  : (std::string(familyName(r->plan.family)) +
                                                     " seed " + std::to_string(r->plan.seed))
                                                        .c_str(),
                        r->generatorError.empty() ? r->outcome.summary().c_str()
                                                  : r->generatorError.c_str());
        std::printf("\n");
    };
    printWorst(
        "Lowest coverage (checker)", [](const Result& r) { return r.outcome.check.coverage; },
        [](const Result& r) { return r.outcome.planned; });
    printWorst(
        "Smallest clearance", [](const Result& r) { return r.outcome.check.clearance.minimum; },
        [](const Result& r) { return r.outcome.planned && !r.outcome.collisionFree; });
    printWorst(
        "Errors (exceptions, generator failures, input errors)",
        [](const Result& r) { return -r.outcome.seconds; },
        [](const Result& r) {
            return !r.generatorError.empty() || r.outcome.otherError || r.outcome.inputError;
        });
    printWorst(
        "Slowest", [](const Result& r) { return -r.outcome.seconds; },
        [](const Result& r) { return r.outcome.planned; });
    return all.failed == 0 ? 0 : 1;
}

// Occupancy maps (issue 15): noisy maps rendered from the sample plans (seeded, ground truth
// known) and real laser maps (tests/data/real-maps, from Debian's mrpt-common), imported
// with the default cleaning and room segmentation, then planned with the default request;
// the largest real map once more without cleaning, and four copies of it joined into one;
// each real map also at half and twice its cell size and turned by 30 degrees.
// Prints a Markdown table per kind (docs/formats.md holds a copy).
//   floorcover-map-bench [--seeds N] [--real-only] [--noisy-only] [--angles A,B,...]
// (--angles: also noisy maps of office, ward and room-obstacle drawn at those angles)
#include "NoisyMap.h"
#include "PathChecker.h"
#include "PlanGenerator.h"
#include "ResampledMap.h"
#include "formats/FileIO.h"
#include "formats/PlanIO.h"
#include "importers/Import.h"
#include "importers/ImportSupport.h"
#include "pipeline/Planner.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

using namespace fc;

namespace {

double seconds(std::chrono::steady_clock::time_point since) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

PlanResult planDefault(const Plan& plan) {
    PlanRequest request;
    request.plan = plan;
    return planCoverage(request);
}

// The independent checker's verdict (tests/checker, Boost.Geometry): its coverage of the
// sweepable area and whether the path keeps L/2 from every wall.
std::string checked(const Plan& plan, const PlanResult& result) {
    const PlanRequest defaults;
    const fccheck::Report r =
        fccheck::checkPath(fcgen::freeSpaceOf(plan), {}, fcgen::polylineOf(result.path.points),
                           defaults.robot.robotDiameter, defaults.robot.coverageWidth);
    char text[64];
    std::snprintf(text, sizeof text, "%.2f%%, %s", 100.0 * r.coverage,
                  r.collisionFree ? "clear" : "**collides**");
    return text;
}

void noisyRows(int seeds) {
    std::printf(
        "| plan | seed | free area vs plan | obstacles | rooms found / true | room IoU "
        "(mean, min) | extra m (map / plan) | extra vs plan | time vs plan | extra m, map as one "
        "room | coverage | checker | import s | plan s |\n"
        "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    const auto dir = std::filesystem::temp_directory_path() / "fc-map-bench";
    std::filesystem::create_directories(dir);
    for (const char* name : {"office", "ward", "simple", "room-obstacle", "room-notches"}) {
        const Plan plan = loadProjectFile(std::string(FC_PLANS_DIR) + "/" + name + ".geojson").plan;
        const PlanResult truth = planDefault(plan);
        for (int seed = 1; seed <= seeds; ++seed) {
            test::NoisyMapOptions options;
            options.seed = static_cast<std::uint64_t>(seed);
            const std::string yaml = test::renderNoisyMap(plan, options)
                                         .write(dir.string(), name + std::to_string(seed));
            auto t0 = std::chrono::steady_clock::now();
            const ImportResult imported = importPlanFile(yaml);
            const double importSeconds = seconds(t0);
            const Plan& cleaned = imported.project.plan;
            std::vector<double> ious = test::roomIoUs(plan, cleaned.rooms);
            t0 = std::chrono::steady_clock::now();
            const PlanResult result = planDefault(cleaned);
            const double planSeconds = seconds(t0);
            char iou[64] = "–";
            if (!ious.empty())
                std::snprintf(iou, sizeof iou, "%.3f, %.3f",
                              std::accumulate(ious.begin(), ious.end(), 0.0) / ious.size(),
                              *std::min_element(ious.begin(), ious.end()));
            const double extra = result.metrics.length - result.metrics.ideal;
            // The same map without room segmentation: what the rooms found cost.
            ImportOptions oneRoom;
            oneRoom.roomSegmentation.method = RoomSegmentationMethod::None;
            const PlanResult whole = planDefault(importPlanFile(yaml, oneRoom).project.plan);
            const double wholeExtra = whole.metrics.length - whole.metrics.ideal;
            const double truthExtra = truth.metrics.length - truth.metrics.ideal;
            // Extra distances compared; where the drawing's plan has almost none (its path
            // is the ideal), the difference as a share of the ideal length instead.
            auto versus = [&](double mapExtra) {
                char text[48];
                if (truthExtra > 0.01 * truth.metrics.ideal)
                    std::snprintf(text, sizeof text, "%+.0f%%",
                                  100.0 * (mapExtra / truthExtra - 1));
                else
                    std::snprintf(text, sizeof text, "%+.1f%% of ideal",
                                  100.0 * (mapExtra - truthExtra) / truth.metrics.ideal);
                return std::string(text);
            };
            // The planner minimises the estimated time (turns cost time too), not the length:
            // the same comparison in time.
            std::printf("| %s | %d | %+.2f%% | %zu | %zu / %zu | %s | %.1f / %.1f | %s | %+.1f%% | "
                        "%.1f (%s) | %.2f%% | %s | %.2f | %.2f |\n",
                        name, seed, 100.0 * (freeAreaOf(cleaned) / freeAreaOf(plan) - 1),
                        cleaned.obstacles.size(), cleaned.rooms.size(), plan.rooms.size(), iou,
                        extra, std::max(truthExtra, 0.0), versus(extra).c_str(),
                        100.0 * (result.metrics.time / truth.metrics.time - 1), wholeExtra,
                        versus(wholeExtra).c_str(), 100.0 * result.metrics.coverage,
                        checked(cleaned, result).c_str(), importSeconds, planSeconds);
            std::fflush(stdout);
        }
    }
}

// Four copies of a map overlaid at offsets (dx, dy) pixels, free where any copy is free,
// else occupied where any is, else unknown: one building four times the size whose copies
// join where their free space overlaps. Written as PGM + YAML into dir; returns the YAML.
std::string joinedCopies(const std::string& name, int dx, int dy,
                         const std::filesystem::path& dir) {
    const std::string base = std::string(FC_REAL_MAPS_DIR) + "/" + name;
    const importing::GreyImage image = importing::readMapImage(base + ".png");
    const int w = image.width + dx, h = image.height + dy;
    std::vector<unsigned char> out(static_cast<size_t>(w) * h, 205);
    for (const auto& [ox, oy] : {std::pair{0, 0}, {dx, 0}, {0, dy}, {dx, dy}})
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) {
                const unsigned char v = image.grey[static_cast<size_t>(y) * image.width + x];
                unsigned char& o = out[static_cast<size_t>(y + oy) * w + x + ox];
                if (v >= 250)
                    o = 254;
                else if (v <= 50 && o != 254)
                    o = 0;
            }
    std::filesystem::create_directories(dir);
    std::ofstream pgm(dir / (name + "-x4.pgm"), std::ios::binary);
    pgm << "P5\n" << w << " " << h << "\n255\n";
    pgm.write(reinterpret_cast<const char*>(out.data()), static_cast<std::streamsize>(out.size()));
    std::ifstream yamlIn(base + ".yaml");
    std::string yamlText((std::istreambuf_iterator<char>(yamlIn)), {});
    yamlText.replace(yamlText.find(name + ".png"), name.size() + 4, name + "-x4.pgm");
    const std::filesystem::path yaml = dir / (name + "-x4.yaml");
    std::ofstream(yaml) << yamlText;
    return yaml.string();
}

void realRows() {
    std::printf("| map | cells | free m² | specks removed | obstacles | rooms | length m | ideal "
                "m | extra / ideal | coverage | checker | unreachable m² | import s | plan s |\n"
                "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    struct RealMap {
        std::string name, yaml;
        bool cleaned;
    };
    auto real = [](const char* name, bool cleaned) {
        return RealMap{std::string(name) + (cleaned ? "" : " (no cleaning)"),
                       std::string(FC_REAL_MAPS_DIR) + "/" + name + ".yaml", cleaned};
    };
    // The largest map as it comes without cleaning (thousands of speckle obstacles), for the
    // planner's speed on what an importer may hand it; and four copies of it joined into one
    // building of 4,650 m^2, for how import and planning grow with the floor.
    const auto dir = std::filesystem::temp_directory_path() / "fc-map-bench";
    std::vector<RealMap> maps{real("uwb-localization-demo", true), real("localization-demo", true),
                              real("telecom-faculty", true), real("telecom-faculty", false),
                              RealMap{"telecom-faculty ×4, joined",
                                      joinedCopies("telecom-faculty", 800, 960, dir), true}};
    // The same buildings at half and twice the cell size and turned by 30 degrees: the
    // cleaning's defaults are meant for 2-10 cm maps drawn at any angle.
    for (const char* name : {"uwb-localization-demo", "localization-demo", "telecom-faculty"})
        for (auto [how, label] : {std::pair{test::Resample::Finer, " (cells halved)"},
                                  {test::Resample::Coarser, " (cells doubled)"},
                                  {test::Resample::Turned30, " (turned 30°)"}})
            maps.push_back({name + std::string(label),
                            test::resampledMap(std::string(FC_REAL_MAPS_DIR) + "/" + name + ".yaml",
                                               how, dir.string()),
                            true});
    for (const RealMap& map : maps) {
        const std::string& yaml = map.yaml;
        const std::string& name = map.name;
        ImportOptions options;
        options.cleaning.enabled = map.cleaned;
        auto t0 = std::chrono::steady_clock::now();
        const ImportResult imported = importPlanFile(yaml, options);
        const double importSeconds = seconds(t0);
        const MapCleaningReport& c = *imported.cleaning;
        t0 = std::chrono::steady_clock::now();
        const PlanResult result = planDefault(imported.project.plan);
        const double planSeconds = seconds(t0);
        const Metrics& m = result.metrics;
        std::printf("| %s | %d×%d | %.0f | %d | %zu | %zu | %.0f | %.0f | %.0f%% | %.2f%% | %s | "
                    "%.1f | %.2f | %.2f |\n",
                    name.c_str(), c.width, c.height, c.freeAreaAfter, c.specksRemoved,
                    imported.project.plan.obstacles.size(), imported.project.plan.rooms.size(),
                    m.length, m.ideal, 100.0 * (m.length - m.ideal) / m.ideal, 100.0 * m.coverage,
                    checked(imported.project.plan, result).c_str(), m.unreachableArea,
                    importSeconds, planSeconds);
        std::fflush(stdout);
    }
}

// Noisy maps (seed 3) of the plans drawn at each of `angles` (degrees), against the drawing
// planned at the same angle: a building drawn at an angle traces as staircase walls, which
// the importer straightens along the dominant direction.
void angledRows(const std::vector<double>& angles) {
    std::printf("| plan | angle | extra m (map / drawing) | extra vs drawing | time vs drawing | "
                "coverage | checker | plan s |\n"
                "|---|---:|---:|---:|---:|---:|---:|---:|\n");
    const auto dir = std::filesystem::temp_directory_path() / "fc-map-bench";
    std::filesystem::create_directories(dir);
    for (const char* name : {"office", "ward", "room-obstacle"}) {
        const Plan upright =
            loadProjectFile(std::string(FC_PLANS_DIR) + "/" + name + ".geojson").plan;
        for (const double angle : angles) {
            const Plan drawing = fcgen::transformPlan(upright, angle, Vec2{0, 0});
            const PlanResult truth = planDefault(drawing);
            test::NoisyMapOptions options;
            options.seed = 3;
            const std::string yaml =
                test::renderNoisyMap(drawing, options)
                    .write(dir.string(),
                           name + std::string("-at-") + std::to_string(static_cast<int>(angle)));
            const Plan traced = importPlanFile(yaml).project.plan;
            const auto t0 = std::chrono::steady_clock::now();
            const PlanResult result = planDefault(traced);
            const double planSeconds = seconds(t0);
            const Metrics& m = result.metrics;
            const double extra = m.length - m.ideal;
            const double truthExtra = truth.metrics.length - truth.metrics.ideal;
            std::printf("| %s | %g° | %.1f / %.1f | %+.0f%% | %+.1f%% | %.2f%% | %s | %.2f |\n",
                        name, angle, extra, truthExtra, 100.0 * (extra / truthExtra - 1),
                        100.0 * (m.time / truth.metrics.time - 1), 100.0 * m.coverage,
                        checked(traced, result).c_str(), planSeconds);
            std::fflush(stdout);
        }
    }
}

} // namespace

int main(int argc, char** argv) {
    int seeds = 2;
    bool real = true, noisy = true;
    std::vector<double> angles;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--seeds") && i + 1 < argc)
            seeds = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--angles") && i + 1 < argc)
            for (const char* at = argv[++i]; *at;) {
                char* end = nullptr;
                angles.push_back(std::strtod(at, &end));
                if (end == at)
                    break;
                at = *end == ',' ? end + 1 : end;
            }
        else if (!std::strcmp(argv[i], "--real-only"))
            noisy = false;
        else if (!std::strcmp(argv[i], "--noisy-only"))
            real = false;
    }
    try {
        if (noisy)
            noisyRows(seeds);
        if (real) {
            std::printf("\n");
            realRows();
        }
        if (!angles.empty()) {
            std::printf("\n");
            angledRows(angles);
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "floorcover-map-bench: %s\n", e.what());
        return 1;
    }
    return 0;
}

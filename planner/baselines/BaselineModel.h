// Internal to baselines/: the Tung & Liu model of one floor, in the sweep frame (stripes
// along +y): cells, their four boustrophedon options, and the transits between points.
#pragma once

#include "baselines/IndependentBaselines.h"

#include <array>
#include <functional>
#include <memory>

namespace fc::baselines::detail {

// Shortest collision-free travel between points: a visibility graph over nodes placed just
// outside the walls' corners, grown by the clearance.
class Transits {
public:
    // cancelled (may be empty) is asked while the graph and the tables are built; when it
    // says so they throw TourError("cancelled").
    Transits(std::vector<Segment> walls, double clearance, std::function<bool()> cancelled = {});
    ~Transits();

    // Whether the robot centre may move straight from p to q (clearance kept from walls).
    bool clear(Vec2 p, Vec2 q) const;
    bool clear(Vec2 p) const;
    // Registers a point; returns its index for distance() and path().
    int addPoint(Vec2 p);
    // After the last addPoint: shortest distances between all registered points (what the
    // GA and the DP need; reeb-cpp routes step by step instead).
    void solve();
    double distance(int from, int to) const; // INFINITY when none
    Polyline path(int from, int to) const;   // from..to; empty when none
    // Shortest path between two arbitrary points (not registered); empty when none.
    // Not safe to call from two threads at once.
    Polyline route(Vec2 p, Vec2 q) const;

private:
    struct Graph;
    std::vector<Segment> walls_;
    double clearance_;
    std::function<bool()> cancelled_;
    void throwIfCancelled() const;
    std::vector<Vec2> nodes_;
    std::unique_ptr<Graph> graph_;
    std::vector<Vec2> points_;
    std::vector<std::vector<double>> nodeDistance_; // point -> node -> distance
    std::vector<std::vector<int>> nodeParent_;      // point -> node -> previous node (-1: point)
    std::vector<std::vector<double>> distance_;     // point -> point
    void placeNodes();
    std::vector<std::pair<int, double>> visibleNodes(Vec2 p) const;
};

// One way to cover a cell: its boustrophedon from one corner in one direction.
struct CoverOption {
    Polyline points;
    double length = INFINITY;  // INFINITY: not drivable
    int entry = -1, exit = -1; // registered transit points
};

struct Stripe {
    double x = 0;
    Interval span; // where the robot centre runs on it
};

struct Cell {
    double x0 = 0, x1 = 0;
    std::vector<Stripe> stripes; // left to right
    std::array<CoverOption, 4> options;
};

struct Model {
    Frame frame;
    std::vector<Cell> cells; // the reachable ones
    // Cells that meet across a slice where one of them begins (left cell, right cell).
    std::vector<std::pair<int, int>> links;
    int cellCount = 0;
    int unreachable = 0;
    std::unique_ptr<Transits> transits;
    int start = -1, end = -1; // registered transit points
};

// Decomposes the rooms' free space, lays out every cell's options and registers their end
// points, the start and the end with the transits. Throws TourError.
// Above maxCells cells (0: no limit) it refuses at once, naming `what` (the baseline).
Model buildModel(const Plan& plan, const std::vector<std::string>& rooms, Vec2 start, Vec2 end,
                 const Options& options, int maxCells = 0, const char* what = "baseline");

// A cell order with options, its cost in the model, and the path it makes (world frame).
double tourCost(const Model& model, const std::vector<int>& order, const std::vector<int>& options);
Tour assembleTour(const Model& model, const std::vector<int>& order,
                  const std::vector<int>& options);

// The GA and the DP on a built model (throw TourError).
Tour solveGa(const Model& model, const Options& options);
Tour solveDp(const Model& model);

} // namespace fc::baselines::detail

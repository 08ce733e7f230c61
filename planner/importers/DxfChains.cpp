// Chaining open lines (LINE, ARC, open polylines) into closed outlines, and the layer roles.
#include "importers/ImportSupport.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <unordered_map>

namespace fc::importing {

namespace {

bool listed(const std::vector<std::string>& layers, const std::string& layer) {
    return std::find(layers.begin(), layers.end(), layer) != layers.end();
}

// Endpoints in a grid of cells `gap` wide: the candidates within `gap` of a point are in
// the 3 x 3 cells around it.
class EndpointGrid {
public:
    EndpointGrid(const std::vector<Piece>& pieces, double gap)
        : cell_(std::max(gap, 1e-9)), pieces_(pieces) {
        for (size_t i = 0; i < pieces.size(); ++i) {
            insert(pieces[i].line.front(), 2 * i);
            insert(pieces[i].line.back(), 2 * i + 1);
        }
    }
    // The nearest unused endpoint (id = 2 * piece + end) within `gap` of p on `layer`, or
    // -1. Looks at a bounded number of candidates so that piles of coincident ends stay fast.
    long long nearest(Vec2 p, double gap, const std::string& layer,
                      const std::vector<bool>& used) const {
        long long best = -1;
        double bestDistance = gap;
        int looked = 0;
        const long long cx = key(p.x), cy = key(p.y);
        for (long long dx = -1; dx <= 1; ++dx)
            for (long long dy = -1; dy <= 1; ++dy) {
                auto it = cells_.find(hash(cx + dx, cy + dy));
                if (it == cells_.end())
                    continue;
                for (size_t id : it->second) {
                    const Piece& piece = pieces_[id / 2];
                    if (used[id / 2] || piece.layer != layer || ++looked > 256)
                        continue;
                    const Vec2 end = id % 2 ? piece.line.back() : piece.line.front();
                    const double d = distance(p, end);
                    if (d <= bestDistance) {
                        bestDistance = d;
                        best = static_cast<long long>(id);
                    }
                }
            }
        return best;
    }

private:
    long long key(double v) const { return static_cast<long long>(std::floor(v / cell_)); }
    static long long hash(long long x, long long y) { return x * 73856093LL ^ y * 19349663LL; }
    void insert(Vec2 p, size_t id) { cells_[hash(key(p.x), key(p.y))].push_back(id); }

    double cell_;
    const std::vector<Piece>& pieces_;
    std::unordered_map<long long, std::vector<size_t>> cells_;
};

void append(Polyline& chain, const Polyline& piece, bool reversed) {
    if (reversed)
        chain.insert(chain.end(), piece.rbegin() + 1, piece.rend());
    else
        chain.insert(chain.end(), piece.begin() + 1, piece.end());
}

} // namespace

Role roleOfLayer(const std::string& layer, const LayerMapping& m) {
    const bool explicitMapping =
        !m.boundary.empty() || !m.obstacles.empty() || !m.rooms.empty() || !m.ignored.empty();
    if (explicitMapping) {
        if (listed(m.ignored, layer))
            return Role::Ignored;
        if (listed(m.boundary, layer))
            return Role::Boundary;
        if (listed(m.obstacles, layer))
            return Role::Obstacle;
        if (listed(m.rooms, layer))
            return Role::Room;
        // Unlisted layers are left out, except that without a boundary list they take part
        // in the geometric rule (the largest outline is the boundary).
        return m.boundary.empty() ? Role::Unassigned : Role::Ignored;
    }
    const std::string guess = guessLayerRole(layer);
    if (guess == "boundary")
        return Role::Boundary;
    if (guess == "obstacles")
        return Role::Obstacle;
    if (guess == "rooms")
        return Role::Room;
    if (guess == "ignored")
        return Role::Ignored;
    return Role::Unassigned;
}

std::vector<Outline> closeChains(std::vector<Piece> pieces, double gap,
                                 std::vector<std::string>& warnings) {
    std::vector<Outline> closed;
    if (pieces.empty())
        return closed;
    const EndpointGrid grid(pieces, gap);
    std::vector<bool> used(pieces.size(), false);
    std::map<std::string, std::pair<size_t, double>> stray; // layer -> (pieces, length)
    for (size_t start = 0; start < pieces.size(); ++start) {
        if (used[start])
            continue;
        used[start] = true;
        const std::string& layer = pieces[start].layer;
        Polyline chain = pieces[start].line;
        size_t count = 1;
        // Grow at the end, then (reversed) at the other end.
        for (int side = 0; side < 2; ++side) {
            while (distance(chain.front(), chain.back()) > gap || chain.size() < 3) {
                const long long id = grid.nearest(chain.back(), gap, layer, used);
                if (id < 0)
                    break;
                const Piece& next = pieces[static_cast<size_t>(id / 2)];
                used[static_cast<size_t>(id / 2)] = true;
                append(chain, next.line, id % 2 == 1);
                ++count;
            }
            if (distance(chain.front(), chain.back()) <= gap && chain.size() >= 3)
                break;
            std::reverse(chain.begin(), chain.end());
        }
        const bool isClosed = chain.size() >= 3 && distance(chain.front(), chain.back()) <= gap;
        if (isClosed) {
            if (distance(chain.front(), chain.back()) == 0)
                chain.pop_back();
            if (chain.size() >= 3 && ringArea(chain) > 0) {
                closed.push_back({std::move(chain), layer});
                continue;
            }
        }
        stray[layer].first += count;
        stray[layer].second += polylineLength(chain);
    }
    for (const auto& [layer, what] : stray) {
        std::ostringstream text;
        text.precision(3);
        text << "layer \"" << layer << "\": " << what.first << " open segment"
             << (what.first == 1 ? "" : "s") << " (" << what.second
             << " m) not closed into an outline; ignored";
        warnings.push_back(text.str());
    }
    return closed;
}

} // namespace fc::importing

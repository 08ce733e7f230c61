#include "canvas/LabelPlacement.h"

#include <QHash>
#include <algorithm>
#include <cmath>
#include <numeric>

namespace fc::ui {

namespace {

// Placed rectangles bucketed in a coarse screen grid, so that thousands of cell labels of
// a big map are placed in about linear time.
class OccupiedGrid {
public:
    bool collides(const QRectF& rect) const {
        bool hit = false;
        forBuckets(rect, [&](quint64 key) {
            for (int index : buckets_.value(key))
                if (rects_[index].intersects(rect))
                    hit = true;
        });
        return hit;
    }
    void add(const QRectF& rect) {
        const int index = static_cast<int>(rects_.size());
        rects_.push_back(rect);
        forBuckets(rect, [&](quint64 key) { buckets_[key].push_back(index); });
    }

private:
    static constexpr double kBucket = 64.0; // pixels
    template <typename F> static void forBuckets(const QRectF& rect, F&& visit) {
        const auto cell = [](double v) { return static_cast<qint64>(std::floor(v / kBucket)); };
        for (qint64 x = cell(rect.left()); x <= cell(rect.right()); ++x)
            for (qint64 y = cell(rect.top()); y <= cell(rect.bottom()); ++y)
                visit((static_cast<quint64>(x) << 32) ^ static_cast<quint32>(y));
    }
    std::vector<QRectF> rects_;
    QHash<quint64, std::vector<int>> buckets_;
};

} // namespace

std::vector<int> placeLabels(const std::vector<LabelRequest>& requests) {
    std::vector<int> chosen(requests.size(), -1);
    std::vector<size_t> order(requests.size());
    std::iota(order.begin(), order.end(), size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        if (requests[a].fixed != requests[b].fixed)
            return requests[a].fixed;
        return requests[a].priority > requests[b].priority;
    });
    OccupiedGrid occupied;
    for (size_t index : order) {
        const LabelRequest& request = requests[index];
        for (size_t c = 0; c < request.candidates.size(); ++c) {
            const QRectF& rect = request.candidates[c];
            if (!rect.isValid() || !std::isfinite(rect.left()) || !std::isfinite(rect.top()))
                continue;
            if (!occupied.collides(rect)) {
                chosen[index] = static_cast<int>(c);
                break;
            }
        }
        if (chosen[index] < 0 && request.fixed && !request.candidates.empty())
            chosen[index] = 0;
        if (chosen[index] >= 0)
            occupied.add(request.candidates[chosen[index]]);
    }
    return chosen;
}

std::vector<QRectF> labelCandidates(QPointF anchor, QSizeF size) {
    const QRectF centred(anchor - QPointF(size.width() / 2, size.height() / 2), size);
    const double gap = 2.0;
    return {centred, centred.translated(0, -size.height() - gap),
            centred.translated(0, size.height() + gap),
            centred.translated(size.width() / 2 + gap, 0),
            centred.translated(-size.width() / 2 - gap, 0)};
}

} // namespace fc::ui

// Collision-aware placement of text labels on screen: room names and cell ids must never
// print over each other ("Cor17dor"). Plain values so that it is tested without a scene.
#pragma once

#include <QRectF>
#include <vector>

namespace fc::ui {

struct LabelRequest {
    // Where the label may go, in screen pixels, best first (centred on its anchor, then
    // nudged above, below, right, left).
    std::vector<QRectF> candidates;
    // Higher is placed first; a label whose every candidate collides is hidden.
    double priority = 0;
    // Markers: placed before all labels and never hidden; at their first candidate that is
    // free, else at their first (start and end at one spot stay side by side).
    bool fixed = false;
};

// For each request, the index of the candidate it gets, or -1 when it is hidden. No two
// placed rectangles intersect unless a fixed one had nowhere else to go.
std::vector<int> placeLabels(const std::vector<LabelRequest>& requests);

// The candidates of a label of size `size` centred at `anchor`: centred, then moved by
// one label height up and down and by its half width plus a gap to the sides.
std::vector<QRectF> labelCandidates(QPointF anchor, QSizeF size);

} // namespace fc::ui

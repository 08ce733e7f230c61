#include "model/CoveragePath.h"

namespace fc {

const char* segmentKindName(SegmentKind kind) {
    switch (kind) {
    case SegmentKind::Stripe:
        return "stripe";
    case SegmentKind::Contour:
        return "contour";
    case SegmentKind::Transit:
        break;
    }
    return "transit";
}

} // namespace fc

// Internal to the GDAL-based importers (DxfImport, PlanAssembly, RosMapImport): GDAL handles
// and OGR polygons to plan rings. Include only from those .cpp files.
#pragma once

#include "importers/ImportSupport.h"

#include <gdal_priv.h>
#include <memory>
#include <ogr_geometry.h>

namespace fc::importing {

struct DatasetCloser {
    void operator()(GDALDataset* d) const { GDALClose(d); }
};
using DatasetPtr = std::unique_ptr<GDALDataset, DatasetCloser>;
using GeometryPtr = std::unique_ptr<OGRGeometry>;

// Appends every polygon of G (a polygon, multipolygon or collection) as shell + holes,
// without the rings' repeated closing points.
void collectPolygons(const OGRGeometry* g, std::vector<Polygon2>& out);

// A ring as a closed OGR ring, and shell and holes as an OGR polygon (owned by the caller, or
// by the geometry they are added to).
OGRLinearRing* ogrRing(const Ring& ring);
OGRPolygon* ogrPolygon(const Ring& shell, const std::vector<Ring>& holes = {});

} // namespace fc::importing

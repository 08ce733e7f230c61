// Internal to the 3D importer: the model as assimp delivered it, in plan coordinates
// (metres, x east, y north, h up), grouped into storeys; and the section of that model.
#pragma once

#include "importers/BuildingModelImport.h"

#include <array>
#include <string>
#include <vector>

namespace fc::building {

struct Point3 {
    double x = 0, y = 0, h = 0;
};
using Triangle = std::array<Point3, 3>;

enum class PartKind { Solid, DoorLeaf, Space };

// One mesh instance of one node (each mesh is sliced and classified on its own).
struct Part {
    std::string node;  // the node's name as assimp gives it
    std::string label; // display name (IfcSpace: LongName, else Name)
    std::string owner; // the element the mesh belongs to: the nearest ancestor (or the node
                       // itself) that is not an assimp helper node ("$Rel...", IfcMappedItem)
    PartKind kind = PartKind::Solid;
    int storey = 0; // index into BuildingModel::storeys
    std::vector<Triangle> triangles;
};

struct Storey {
    std::string name;
    double elevation = 0; // m, the floor's height
};

struct BuildingModel {
    std::string format;             // "ifc", "obj", "gltf", "glb", "stl"
    std::vector<Storey> storeys;    // lowest first
    std::vector<Part> parts;        // in node order
    std::vector<std::string> nodes; // owners of meshes (see Part::owner), in file order
    bool unitless = true;           // false for IFC (assimp converts to metres)
};

struct Source {
    const void* data = nullptr; // bytes in memory, or
    std::size_t size = 0;
    std::string path;      // a file (glTF may refer to side files)
    std::string extension; // lower case, no dot
};

// Reads the model with assimp. metresPerUnit scales every coordinate. Throws InputError
// (message without the file name).
BuildingModel loadBuildingModel(const Source& source, UpAxis up, double metresPerUnit);

// Segments cut from the triangles of `part` by the plane h = height. Vertices exactly on the
// plane count as above it, so closed meshes give closed section curves.
std::vector<Segment> slicePart(const Part& part, double height);

// Meshes assimp delivers are not always closed (IFC walls with openings): a section chain that
// ends somewhere is closed by joining the loose ends pairwise, nearest pairs first, so that
// inside/outside parity holds. Parts with more than kMaxOpenEnds loose ends are left alone.
constexpr size_t kMaxOpenEnds = 400;
void closeOpenChains(std::vector<Segment>& segments);

} // namespace fc::building

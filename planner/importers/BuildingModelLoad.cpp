// Loading a 3D building model with assimp into plan coordinates (see BuildingModel.h).
#include "importers/BuildingModel.h"
#include "importers/IfcNames.h"
#include "model/Plan.h"

#include <algorithm>
#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <set>

namespace fc::building {

namespace {

constexpr int kMaxNodeDepth = 256;
constexpr double kMaxCoordinate = 1e7; // m: beyond this the model is hostile or mis-scaled

bool startsWith(const std::string& s, const char* prefix) {
    return s.rfind(prefix, 0) == 0;
}

std::string firstLine(std::string text) {
    text = text.substr(0, text.find('\n'));
    while (!text.empty() && (text.back() == ' ' || text.back() == '\r'))
        text.pop_back();
    return text.empty() ? "unknown assimp error" : text;
}

// "IfcSpace_Kueche_3XKNTrXCz5g9BsmhXXKfBm" -> "Kueche".
std::string ifcNameOfNode(const std::string& node) {
    std::string rest = node.substr(std::min(node.size(), node.find('_') + 1));
    if (!ifcGuidOfNode(node).empty())
        rest = rest.substr(0, rest.size() >= 23 ? rest.size() - 23 : 0);
    return rest.empty() ? node : rest;
}

struct Walker {
    explicit Walker(const aiScene& s) : scene(s) {}
    const aiScene& scene;
    bool ifc = false;
    bool yUp = true;
    double scale = 1;
    std::map<std::string, IfcNames> ifcNames;
    BuildingModel model;
    std::set<std::string> seenNodes;
    size_t triangles = 0;

    Point3 toPlan(const aiVector3D& v) const {
        return yUp ? Point3{v.x * scale, -v.z * scale, v.y * scale}
                   : Point3{v.x * scale, v.y * scale, v.z * scale};
    }

    std::string ifcLabel(const std::string& node, bool preferLong) const {
        const auto it = ifcNames.find(ifcGuidOfNode(node));
        if (it != ifcNames.end()) {
            const IfcNames& n = it->second;
            if (preferLong && !n.longName.empty())
                return n.longName;
            if (!n.name.empty())
                return n.name;
        }
        return ifcNameOfNode(node);
    }

    void addMesh(const aiNode& node, const aiMesh& mesh, const aiMatrix4x4& world, PartKind kind,
                 int storey, const std::string& owner) {
        Part part;
        part.node = node.mName.C_Str();
        part.owner = owner;
        part.kind = kind;
        part.storey = storey;
        part.label = ifc ? ifcLabel(part.node, kind == PartKind::Space) : part.node;
        triangles += mesh.mNumFaces;
        if (triangles > kMaxBuildingModelTriangles)
            throw InputError("more than " + std::to_string(kMaxBuildingModelTriangles) +
                             " triangles");
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const aiFace& face = mesh.mFaces[f];
            if (face.mNumIndices != 3)
                continue; // points and lines have no section
            Triangle t;
            for (int k = 0; k < 3; ++k) {
                if (face.mIndices[k] >= mesh.mNumVertices)
                    throw InputError("node \"" + part.node + "\" indexes a missing vertex");
                t[k] = toPlan(world * mesh.mVertices[face.mIndices[k]]);
                for (double c : {t[k].x, t[k].y, t[k].h})
                    if (!std::isfinite(c) || std::abs(c) > kMaxCoordinate)
                        throw InputError("node \"" + part.node +
                                         "\" has a non-finite or huge coordinate");
            }
            part.triangles.push_back(t);
        }
        if (!part.triangles.empty())
            model.parts.push_back(std::move(part));
    }

    void walk(const aiNode& node, const aiMatrix4x4& parent, int storey, PartKind kind,
              std::string owner, int depth) {
        if (depth > kMaxNodeDepth)
            throw InputError("the node tree is deeper than " + std::to_string(kMaxNodeDepth));
        const aiMatrix4x4 world = parent * node.mTransformation;
        const std::string name = node.mName.C_Str();
        if (owner.empty() || !(startsWith(name, "$") || startsWith(name, "IfcMappedItem")))
            owner = name;
        if (ifc) {
            if (startsWith(name, "IfcOpeningElement_"))
                return; // voids, already cut from their walls
            if (startsWith(name, "IfcBuildingStorey_")) {
                storey = static_cast<int>(model.storeys.size());
                // The storey's elevation: the height of its placement's origin.
                model.storeys.push_back({ifcLabel(name, false), toPlan(world * aiVector3D()).h});
            } else if (startsWith(name, "IfcSpace_")) {
                kind = PartKind::Space;
            } else if (startsWith(name, "IfcDoor_")) {
                kind = PartKind::DoorLeaf;
            }
        }
        if (node.mNumMeshes > 0 && seenNodes.insert(owner).second)
            model.nodes.push_back(owner);
        for (unsigned i = 0; i < node.mNumMeshes; ++i) {
            if (node.mMeshes[i] >= scene.mNumMeshes)
                throw InputError("node \"" + name + "\" refers to a missing mesh");
            addMesh(node, *scene.mMeshes[node.mMeshes[i]], world, kind, storey, owner);
        }
        for (unsigned c = 0; c < node.mNumChildren; ++c)
            walk(*node.mChildren[c], world, storey, kind, owner, depth + 1);
    }
};

std::string fileText(const std::string& path) { // size already checked by the caller
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

bool isYUp(const std::string& extension, UpAxis up) {
    if (up != UpAxis::Automatic)
        return up == UpAxis::Y;
    return extension != "stl";
}

} // namespace

BuildingModel loadBuildingModel(const Source& source, UpAxis up, double metresPerUnit) {
    const auto& known = buildingModelExtensions();
    if (std::find(known.begin(), known.end(), source.extension) == known.end())
        throw InputError("unsupported 3D model format \"." + source.extension + "\"");
    Assimp::Importer importer;
    importer.SetPropertyBool(AI_CONFIG_IMPORT_IFC_SKIP_SPACE_REPRESENTATIONS, false);
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                                aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    const unsigned flags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                           aiProcess_SortByPType | aiProcess_ValidateDataStructure;
    const aiScene* scene =
        source.data
            ? importer.ReadFileFromMemory(source.data, source.size, flags, source.extension.c_str())
            : importer.ReadFile(source.path, flags);
    if (!scene)
        throw InputError("cannot read the model: " + firstLine(importer.GetErrorString()));
    if (!scene->mRootNode || scene->mNumMeshes == 0 || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE))
        throw InputError("the model holds no meshes");

    Walker walker(*scene);
    walker.ifc = source.extension == "ifc";
    walker.yUp = isYUp(source.extension, up);
    walker.scale = metresPerUnit;
    walker.model.format = source.extension;
    walker.model.unitless = !walker.ifc;
    if (walker.ifc) {
        if (source.data)
            walker.ifcNames =
                readIfcNames(std::string(static_cast<const char*>(source.data), source.size));
        else
            walker.ifcNames = readIfcNames(fileText(source.path));
    }
    walker.walk(*scene->mRootNode, aiMatrix4x4(), -1, PartKind::Solid, "", 0);
    BuildingModel& model = walker.model;
    if (model.parts.empty())
        throw InputError("the model holds no triangles");
    if (model.storeys.empty()) { // one storey: the whole model, its floor the lowest point
        double lowest = std::numeric_limits<double>::infinity();
        for (Part& part : model.parts) {
            part.storey = 0;
            for (const Triangle& t : part.triangles)
                for (const Point3& p : t)
                    lowest = std::min(lowest, p.h);
        }
        model.storeys.push_back({"whole model", lowest});
    }
    // Lowest first; parts follow their storey's new index.
    std::vector<int> order(model.storeys.size());
    for (size_t i = 0; i < order.size(); ++i)
        order[i] = static_cast<int>(i);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
        return model.storeys[a].elevation < model.storeys[b].elevation;
    });
    std::vector<int> newIndex(order.size());
    std::vector<Storey> sorted;
    for (size_t i = 0; i < order.size(); ++i) {
        newIndex[order[i]] = static_cast<int>(i);
        sorted.push_back(model.storeys[order[i]]);
    }
    model.storeys = std::move(sorted);
    for (Part& part : model.parts)
        part.storey = part.storey >= 0 ? newIndex[part.storey] : -1;
    return model;
}

std::vector<Segment> slicePart(const Part& part, double height) {
    std::vector<Segment> segments;
    for (const Triangle& t : part.triangles) {
        Vec2 cut[2];
        int n = 0;
        for (int k = 0; k < 3 && n < 2; ++k) {
            Point3 a = t[k], b = t[(k + 1) % 3];
            const bool aAbove = a.h >= height, bAbove = b.h >= height;
            if (aAbove == bAbove)
                continue;
            if (aAbove)
                std::swap(a, b); // always interpolate from the lower end: shared edges agree
            const double s = (height - a.h) / (b.h - a.h);
            cut[n++] = {a.x + s * (b.x - a.x), a.y + s * (b.y - a.y)};
        }
        if (n == 2 && cut[0] != cut[1])
            segments.push_back({cut[0], cut[1]});
    }
    return segments;
}

void closeOpenChains(std::vector<Segment>& segments) {
    std::map<std::pair<double, double>, int> degree;
    for (const Segment& s : segments) {
        ++degree[{s.a.x, s.a.y}];
        ++degree[{s.b.x, s.b.y}];
    }
    std::vector<Vec2> ends;
    for (const auto& [p, count] : degree)
        if (count % 2 == 1)
            ends.push_back({p.first, p.second});
    if (ends.size() > kMaxOpenEnds)
        return;
    struct Pair {
        double length;
        size_t i, j;
    };
    std::vector<Pair> pairs;
    for (size_t i = 0; i < ends.size(); ++i)
        for (size_t j = i + 1; j < ends.size(); ++j)
            pairs.push_back({distance(ends[i], ends[j]), i, j});
    std::sort(pairs.begin(), pairs.end(),
              [](const Pair& a, const Pair& b) { return a.length < b.length; });
    std::vector<bool> joined(ends.size(), false);
    for (const Pair& pair : pairs) {
        if (joined[pair.i] || joined[pair.j])
            continue;
        joined[pair.i] = joined[pair.j] = true;
        segments.push_back({ends[pair.i], ends[pair.j]});
    }
}

} // namespace fc::building

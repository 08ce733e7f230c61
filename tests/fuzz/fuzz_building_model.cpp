// libFuzzer target for the 3D building-model importer (issue 5). The first byte picks the
// reader ('o' OBJ, 's' STL, 'g' glTF, 'b' GLB, 'i' IFC; other values modulo 5), the rest is
// the file. Any outcome but a plan or an InputError (a crash, a sanitizer report, another
// exception, a hang) is a finding.
#include "importers/BuildingModelImport.h"

#include <cstddef>
#include <cstdint>

namespace {

const char* extensionFor(uint8_t selector) {
    switch (selector) {
    case 'o':
        return "obj";
    case 's':
        return "stl";
    case 'g':
        return "gltf";
    case 'b':
        return "glb";
    case 'i':
        return "ifc";
    default:
        static const char* const all[] = {"obj", "stl", "gltf", "glb", "ifc"};
        return all[selector % 5];
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size < 1 || size > (1u << 20))
        return 0;
    try {
        fc::importBuildingModelFromMemory(data + 1, size - 1, extensionFor(data[0]), {});
    } catch (const fc::InputError&) {
    }
    return 0;
}

// Internal to the 3D importer: names assimp does not pass on. assimp names an IFC node
// "IfcSpace_<Name>_<GlobalId>"; the LongName ("Kueche" for space "1") and the unmangled storey
// name are read here from the STEP text, keyed by the 22-character GlobalId.
#pragma once

#include <map>
#include <string>

namespace fc::building {

struct IfcNames {
    std::string name;
    std::string longName;
};

// IFCSPACE and IFCBUILDINGSTOREY entities of an IFC2x3 STEP file, by GlobalId. Strings are
// decoded from STEP's \S\, \X\ and \X2\ escapes to UTF-8. Unparsable entities are skipped.
std::map<std::string, IfcNames> readIfcNames(const std::string& stepText);

// The 22-character GlobalId at the end of an assimp IFC node name, or "" if there is none.
std::string ifcGuidOfNode(const std::string& nodeName);

} // namespace fc::building

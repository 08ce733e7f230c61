// The planner's messages about 3D building models (IFC, OBJ, glTF, STL: reading the model,
// cutting it at a height, turning the cut into a plan) and about separating an occupancy
// map's rooms, and the editor's sentences for them. The patterns follow the planner's wording
// in planner/importers (BuildingModelImport.cpp, BuildingModelLoad.cpp,
// SectionArrangement.cpp, MapRooms.cpp). A model comes in with File > Import…, which opens
// the Import 3D Building Model dialog (Storey, Cut above the floor, Unit, Up axis). Most of
// these messages come after the model's path; plainMessage keeps the path and rewords the
// rest.
#include "document/PlannerMessageForms.h"

#include <QCoreApplication>

namespace fc::ui::messages {

std::vector<MessageForm> modelMessageForms() {
    return {
        // Reading the model (importers/BuildingModelImport.cpp, BuildingModelLoad.cpp).
        messageForm(R"re(^cannot read the file \((.*)\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "The file cannot be read (%1).")),
        messageForm(R"re(^the file is empty$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "The file is empty.")),
        messageForm(R"re(^the file is larger than (.*)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The file is larger than %1, more than FloorCover "
                                      "imports.")),
        messageForm(
            R"re(^the model is too large$)re",
            QT_TRANSLATE_NOOP("PlannerMessages", "The model is larger than FloorCover imports.")),
        messageForm(R"re(^out of memory while reading the model$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "FloorCover ran out of memory while reading the model: "
                                      "close other programs, or export a smaller part of the "
                                      "building.")),
        messageForm(R"re(^unsupported 3D model format "(.*)"$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "FloorCover imports 3D building models as .ifc, .obj, "
                                      ".gltf, .glb or .stl files, not as “%1” files.")),
        messageForm(R"re(^cannot read the model: (.*)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The model cannot be read (%1): export it again from the "
                                      "modelling program.")),
        messageForm(R"re(^the model holds no meshes$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The model holds no 3D shapes (meshes) to cut: export it "
                                      "again with its geometry.")),
        messageForm(R"re(^the model holds no triangles$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The model holds no surfaces (triangles) to cut: export "
                                      "it again with its geometry.")),
        messageForm(R"re(^more than (\d+) triangles$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The model has more than %1 triangles, more than "
                                      "FloorCover imports: export only the storey you need.")),
        messageForm(R"re(^the node tree is deeper than (\d+)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The model's parts are nested more than %1 levels deep, "
                                      "more than FloorCover imports.")),
        messageForm(R"re(^node "(.*)" (?:indexes a missing vertex|refers to a missing mesh)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The model is damaged (its part “%1” refers to geometry "
                                      "that is missing): export it again.")),
        messageForm(R"re(^node "(.*)" has a non-finite or huge coordinate$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The model's part “%1” has an invalid or huge "
                                      "coordinate: check the Unit in the Import 3D Building "
                                      "Model dialog.")),

        // Cutting the model (importers/BuildingModelImport.cpp, SectionArrangement.cpp). The
        // cut is said "at height 1.3 m (storey \"Ground floor\" floor + 0.3 m)".
        messageForm(R"re(^metres per unit must be a positive number$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The unit must be a positive number of metres: choose "
                                      "another Unit in the Import 3D Building Model dialog.")),
        messageForm(R"re(^the slice height must be a positive number of metres$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "“Cut above the floor” must be a positive number of "
                                      "metres.")),
        messageForm(R"re(^no storey "(.*)" \(the model has (.*)\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The model has no storey “%1” (its storeys: %2): choose "
                                      "one under Storey.")),
        messageForm(R"re(^no section at height (.+?) \(storey "(.*)" floor \+ (.+?)\): the )re"
                    R"re(plane cuts no wall$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The cut at height %1 (%3 above the floor of storey “%2”) "
                                      "meets no wall: lower “Cut above the floor”, or check the "
                                      "Unit and the Storey.")),
        messageForm(R"re(^the section at height (.+?) \(storey "(.*)" floor \+ (.+?)\) has )re"
                    R"re(more than (\d+) segments$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The cut at height %1 (%3 above the floor of storey “%2”) "
                                      "has more than %4 wall edges, more than FloorCover "
                                      "imports: try another “Cut above the floor”.")),
        messageForm(R"re(^the section encloses no free space \(the outer walls are open at )re"
                    R"re(that height, or the model is not closed\) at height (.+?) \(storey )re"
                    R"re("(.*)" floor \+ (.+?)\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The cut at height %1 (%3 above the floor of storey “%2”) "
                                      "encloses no free space: the outer walls are open at that "
                                      "height, or the model is not closed. Try another “Cut "
                                      "above the floor”.")),
        messageForm(R"re(^the section at height (.+?) \(storey "(.*)" floor \+ (.+?)\) is not )re"
                    R"re(a valid plan: (?<message>.+)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The cut at height %1 (%3 above the floor of storey “%2”) "
                                      "makes no valid plan: %4")),
        messageForm(R"re(^(\d+) smaller enclosed region\(s\) left out \((.*) m\^2 in all\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "Smaller enclosed areas apart from the main floor, left "
                                      "out: %1 (%2 m² in all).")),
        messageForm(R"re(^space "(.*)" has no closed section$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "Space “%1” has no closed outline at the cut height and "
                                      "is left out as a room.")),
        messageForm(R"re(^room "(.*)" left out: (?<message>.+)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "Room “%1” is left out: %2")),

        // Separating an occupancy map's rooms (importers/MapRooms.cpp).
        messageForm(R"re(^separating the rooms failed$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The map's rooms could not be separated: choose One room "
                                      "under “Split into rooms”, or another way to split.")),
    };
}

} // namespace fc::ui::messages

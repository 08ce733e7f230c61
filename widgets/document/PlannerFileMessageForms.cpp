// The planner's messages about files (reading, importing, exporting) and the tiling robot, and
// the editor's sentences for them. The patterns follow the planner's wording in
// planner/formats, planner/importers and planner/tiling. Most of these messages come after
// the file's path ("plan.geojson: feature 3 has no geometry"); plainMessage keeps the path
// and rewords the rest.
#include "document/PlannerMessageForms.h"

#include <QCoreApplication>

namespace fc::ui::messages {

std::vector<MessageForm> fileMessageForms() {
    return {
        // Reading and writing files (formats/FileIO.cpp, importers/Import.cpp).
        messageForm(R"re(^(?:no such file|cannot open \(no such file\))$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "There is no such file.")),
        messageForm(R"re(^cannot open \(it is a directory\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "This is a folder, not a file.")),
        messageForm(R"re(^cannot (?:open|read) \((.*)\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "The file cannot be read (%1).")),
        messageForm(R"re(^cannot write \((.*)\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The file cannot be written (%1): choose another folder, or "
                                      "check that this one can be written to.")),
        messageForm(
            R"re(^unsupported file type \(no extension\); expected a \.fcproj project or )re"
            R"re(a \.geojson/\.json plan$)re",
            QT_TRANSLATE_NOOP("PlannerMessages",
                              "The file name has no extension: FloorCover opens .fcproj "
                              "projects and .geojson or .json plans; other formats come "
                              "in with File > Import…")),
        messageForm(R"re(^unsupported file type "(.*)"; expected a \.fcproj project or a )re"
                    R"re(\.geojson/\.json plan$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "FloorCover opens .fcproj projects and .geojson or .json "
                                      "plans, not “%1” files; other formats come in with File > "
                                      "Import…")),
        messageForm(R"re(^file larger than (.*)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The file is larger than %1, more than FloorCover "
                                      "imports.")),

        // JSON (formats/JsonSupport.cpp).
        messageForm(R"re(^file is empty$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "The file is empty.")),
        messageForm(R"re(^truncated JSON: parse error at line (\d+), column (\d+): .*$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The file ends too early (line %1, column %2): it may have "
                                      "been cut off while it was written.")),
        messageForm(R"re(^truncated JSON: .*$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The file ends too early: it may have been cut off while it "
                                      "was written.")),
        messageForm(R"re(^invalid JSON: parse error at line (\d+), column (\d+): (.*)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The file is not valid JSON at line %1, column %2 (%3).")),
        messageForm(R"re(^invalid JSON: (.*)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "The file is not valid JSON (%1).")),
        messageForm(
            R"re(^number (.*) at line (\d+), column (\d+) is out of range \(not a finite )re"
            R"re(coordinate\)$)re",
            QT_TRANSLATE_NOOP("PlannerMessages",
                              "The number %1 at line %2, column %3 is too large for a "
                              "coordinate.")),
        messageForm(
            R"re(^number (.*) is out of range \(not a finite coordinate\)$)re",
            QT_TRANSLATE_NOOP("PlannerMessages", "The number %1 is too large for a coordinate.")),
        messageForm(
            R"re(^a number is out of range: (.*)$)re",
            QT_TRANSLATE_NOOP("PlannerMessages", "A number in the file is out of range (%1).")),
        messageForm(
            R"re(^{ring}: coordinates must be an array of \[x, y\] positions \(got (.*)\)$)re",
            QT_TRANSLATE_NOOP("PlannerMessages",
                              "%1: the coordinates must be a list of [x, y] positions, "
                              "not %2.")),
        messageForm(R"re(^{ring}: vertex (\d+) is not an \[x, y\] position \(got (.*)\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "%1: vertex %2 is not an [x, y] position but %3.")),
        messageForm(R"re(^{ring}: vertex (\d+) has a non-numeric coordinate \(got (.*)\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "%1: vertex %2 has a coordinate that is not a number "
                                      "(%3).")),
        messageForm(R"re(^{ring}: vertex (\d+) has a non-finite coordinate$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "%1: vertex %2 has a coordinate that is not a finite "
                                      "number.")),

        // GeoJSON plans (formats/GeoJsonPlan.cpp).
        messageForm(R"re(^{ring} has no geometry$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "%1 has no geometry.")),
        messageForm(R"re(^{ring}: geometry has no type$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "%1: the geometry has no type.")),
        messageForm(R"re(^{ring}: geometry type "(.*)" is not supported \(expected Polygon\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "%1 is a %2; FloorCover reads plans drawn as polygons.")),
        messageForm(
            R"re(^{ring}: (?:\w+ has no coordinates array|\w+ has no polygons|polygon has )re"
            R"re(no rings)$)re",
            QT_TRANSLATE_NOOP("PlannerMessages", "%1: the geometry holds no polygon outline.")),
        messageForm(R"re(^{ring}: properties\.name must be a string \(got (.*)\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "%1: the room name (properties.name) must be text, not "
                                      "%2.")),
        messageForm(R"re(^{ring} has no name \(rooms need properties\.name\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "%1 has no name: rooms need one in properties.name.")),
        messageForm(R"re(^(\d+) buildings \(boundary polygons of (.*) m2, largest first\); a )re"
                    R"re(plan holds one building: choose one with --building K, K = 1\.\.\d+ )re"
                    R"re(\(.*\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The file holds %1 buildings (outer walls of %2 m², "
                                      "largest first), and a plan holds one: choose one as "
                                      "you open it.")),
        messageForm(R"re(^{ring} has a hole; free space inside an obstacle is not supported$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "%1 has a hole; floor inside an obstacle is not "
                                      "supported.")),
        messageForm(R"re(^duplicate room name "(.*)" \(features (\d+) and (\d+)\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "Two rooms are named “%1” (features %2 and %3): rename "
                                      "one.")),
        messageForm(R"re(^{ring} is a MultiPolygon with (\d+) parts; split it into separately )re"
                    R"re(named rooms$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "%1 has %2 separate parts: split it into rooms with names "
                                      "of their own.")),
        messageForm(R"re(^{ring} has a hole; model the hole as an obstacle instead$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "%1 has a hole: draw the hole as an obstacle instead.")),
        messageForm(R"re(^not a GeoJSON FeatureCollection \(.*\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The file is not a GeoJSON FeatureCollection, the form in "
                                      "which FloorCover reads plans.")),
        messageForm(
            R"re(^the FeatureCollection has no "features" array$)re",
            QT_TRANSLATE_NOOP("PlannerMessages", "The GeoJSON file has no list of features.")),
        messageForm(R"re(^{ring} is not a GeoJSON Feature object$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "%1 is not a GeoJSON Feature.")),
        messageForm(R"re(^{ring}: properties must be an object$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "%1: its properties must be an object.")),
        messageForm(
            R"re(^{ring} has no properties\.role \(expected boundary, obstacle or room\)$)re",
            QT_TRANSLATE_NOOP("PlannerMessages",
                              "%1 has no role: set properties.role to boundary, obstacle "
                              "or room.")),
        messageForm(R"re(^{ring}: properties\.role must be a string \(got (.*)\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "%1: the role (properties.role) must be text, not %2.")),
        messageForm(
            R"re(^{ring} has unknown role "(.*)" \(expected boundary, obstacle or room\)$)re",
            QT_TRANSLATE_NOOP("PlannerMessages",
                              "%1 has the unknown role “%2”: use boundary, obstacle or "
                              "room.")),
        messageForm(R"re(^no boundary: one feature needs properties\.role = "boundary"$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The plan has no outer wall: one feature needs "
                                      "properties.role = \"boundary\".")),

        // Projects (formats/ProjectFile.cpp).
        messageForm(R"re(^(\w+\.\w+) must be a finite number \(got (.*)\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "In the project file, %1 must be a finite number, not %2.")),
        messageForm(
            R"re(^(\w+\.\w+) must be an object$)re",
            QT_TRANSLATE_NOOP("PlannerMessages", "In the project file, %1 must be an object.")),
        messageForm(R"re(^(start|end) must be \[x, y\] or null \(got (.*)\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "In the project file, %1 must be [x, y] or null, not %2.")),
        messageForm(R"re(^(start|end) has a non-finite coordinate$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "In the project file, %1 has a coordinate that is not a "
                                      "finite number.")),
        messageForm(R"re(^plan has no boundary$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The project's plan has no outer wall (boundary).")),
        messageForm(
            R"re(^(plan\.obstacles|plan\.rooms) must be an array(?: of rings)?$)re",
            QT_TRANSLATE_NOOP("PlannerMessages", "In the project file, %1 must be a list.")),
        messageForm(R"re(^{ring} has no outline$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "%1 has no outline.")),
        messageForm(R"re(^plan\.epsg must be a positive integer EPSG code \(got (.*)\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "In the project file, plan.epsg must be an EPSG code (a "
                                      "positive whole number), not %1.")),
        messageForm(R"re(^not a FloorCover project \(.*\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "The file is not a FloorCover project.")),
        messageForm(R"re(^project has no integer "version"$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The project file does not say its format version.")),
        messageForm(R"re(^project format version (\d+) is newer than this FloorCover supports )re"
                    R"re(\((\d+)\); update FloorCover$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The project was saved by a newer FloorCover (format "
                                      "version %1; this one reads up to %2): update "
                                      "FloorCover.")),
        messageForm(R"re(^project format version (-?\d+) is invalid$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The project file has an invalid format version (%1).")),
        messageForm(R"re(^project has no "plan" object$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "The project file holds no plan.")),
        messageForm(R"re(^sweep\.(automatic|per_room) must be true or false$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "In the project file, sweep.%1 must be true or false.")),
        messageForm(R"re(^sweep\.room_angles must map room names to angles in degrees$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "In the project file, sweep.room_angles must give each "
                                      "room's sweep angle in degrees.")),
        messageForm(R"re(^sweep\.room_angles\["(.*)"\] must be a finite number of degrees )re"
                    R"re(\(got (.*)\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "In the project file, the sweep angle of room “%1” must be "
                                      "a finite number of degrees, not %2.")),
        messageForm(R"re(^solver must be a string \(got (.*)\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "In the project file, solver must be the name of a solver, "
                                      "not %1.")),
        messageForm(R"re(^selectedRooms must (?:be an array of room names|hold room names )re"
                    R"re(\(got .*\))$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "In the project file, selectedRooms must be a list of room "
                                      "names.")),

        // Exports (formats/ExportFormats.cpp).
        messageForm(R"re(^unknown export format "(.*)" \(expected (.*)\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "FloorCover cannot export to “%1” (it exports %2).")),
        messageForm(R"re(^unknown export subject "(.*)" \(expected path, plan or zones\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "FloorCover cannot export “%1”: it exports the path, the "
                                      "plan or the zones.")),
        messageForm(R"re(^format (\S+) cannot hold the path$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The %1 format cannot hold the path: choose another "
                                      "format.")),
        messageForm(R"re(^format (\S+) cannot hold the plan$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The %1 format cannot hold the plan: choose another "
                                      "format.")),
        messageForm(R"re(^format (\S+) cannot hold the zones$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The %1 format cannot hold the zones: choose another "
                                      "format.")),
        messageForm(R"re(^unknown export format$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "FloorCover does not know this export format: choose one of "
                                      "the formats offered.")),

        // Imports (importers/Import.cpp).
        messageForm(R"re(^unknown plan format "\.(.*)" \(importable: (.*)\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "FloorCover cannot import “.%1” files (it imports %2).")),
        messageForm(R"re(^unknown plan format "\.(.*)"$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "FloorCover cannot import “.%1” files.")),
        messageForm(
            R"re(^the unit must be a positive number of metres below 1,000,000 \(metres per drawing unit: 0\.001 for millimetres\)$)re",
            QT_TRANSLATE_NOOP("PlannerMessages",
                              "The unit must be a positive number of metres below "
                              "1,000,000 (0.001 for a drawing in millimetres): correct "
                              "Units in the import dialog.")),
        messageForm(R"re(^EPSG code (-?\d+) is not valid \(codes run from 1 to (\d+)\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The file names EPSG code %1, which is not valid (codes run "
                                      "from 1 to %2).")),
        messageForm(R"re(^point \((.*), (.*)\) in EPSG:(\d+) is not on the globe$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The point (%1, %2) in EPSG:%3 is not on the globe: are "
                                      "the coordinates in that system?")),
        messageForm(
            R"re(^not a JSON text file \(a NUL byte at offset (\d+)\): is it a binary file\?$)re",
            QT_TRANSLATE_NOOP("PlannerMessages",
                              "The file is not JSON text (it holds a zero byte at offset "
                              "%1): is it a binary file?")),
        messageForm(R"re(^the opening radius must be at most (.*) m \(got (.*) m\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "“Fill notches up to” must be at most %1 m, not %2 m.")),
        messageForm(R"re(^the closing radius must be at most (.*) m \(got (.*) m\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "“Remove obstacles up to” must be at most %1 m, not %2 m.")),
        messageForm(R"re(^the gap tolerance must be between 0 and 1000 m$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "“Close gaps up to” must be between 0 and 1000 m.")),
        messageForm(R"re(^the plan needs repair: (?<message>.+)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The plan needs repair (Plan > Repair Plan, after the "
                                      "import): %1")),
        messageForm(R"re(^the start pose \((.*), (.*)\) is not in the free space; not used$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The map's start pose (%1, %2) is not on the free floor; it "
                                      "was not used.")),

        // ROS maps and their images (importers/MapImage.cpp, RosMapImport.cpp, RosMapYaml.cpp,
        // MapTracing.cpp).
        messageForm(R"re(^map image pixels are (.*) \(expected 1- to 16-bit unsigned grey or )re"
                    R"re(colour\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The map image's pixels are %1; FloorCover reads 1- to "
                                      "16-bit grey or colour images.")),
        messageForm(R"re(^map image (.*) is not a readable PNG/PGM/BMP/TIFF$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The map image %1 is not a readable PNG, PGM, BMP or TIFF "
                                      "image.")),
        messageForm(R"re(^map image is empty$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "The map image is empty.")),
        messageForm(R"re(^map image larger than (\d+) pixels$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The map image has more than %1 pixels, more than "
                                      "FloorCover reads.")),
        messageForm(R"re(^map image unreadable: (.*)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "The map image cannot be read (%1).")),
        messageForm(R"re(^map image uses a colour missing from its palette$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The map image uses a colour that its palette lacks.")),
        messageForm(R"re(^map image (.*) not found$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The map image %1 named in the YAML file is missing: keep "
                                      "it next to the YAML file.")),
        messageForm(R"re(^every cell of the map is unknown: nothing was mapped$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "Every cell of the map is unknown: the map shows nothing.")),
        messageForm(R"re(^the map has no free (?:cells|space)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "The map has no free floor.")),
        messageForm(R"re(^cleaning left no free space \(the map's free cells are specks\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "Cleaning the map left no free floor (its free cells are "
                                      "specks): lower “Drop islands below” under Clean the "
                                      "map.")),
        messageForm(R"re(^the free space is thinner than a pixel everywhere$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The free floor is thinner than a pixel everywhere.")),
        messageForm(R"re(^(\w+): "(.*)" is not a number$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "In the map's YAML file, %1 “%2” is not a number.")),
        messageForm(R"re(^(\w+): expected a list \[(.*)\]$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "In the map's YAML file, %1 must be a list [%2].")),
        messageForm(R"re(^(\w+): expected (\d+) numbers, found (\d+)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "In the map's YAML file, %1 needs %2 numbers, not %3.")),
        messageForm(R"re(^(\w+): "(.*)" is not 0/1 or true/false$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "In the map's YAML file, %1 “%2” is not 0/1 or "
                                      "true/false.")),
        messageForm(R"re(^map YAML larger than 1 MiB$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The map's YAML file is larger than 1 MiB; a ROS map's is "
                                      "far smaller.")),
        messageForm(R"re(^line (\d+): expected "key: value"$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "Line %1 of the map's YAML file is not of the form “key: "
                                      "value”.")),
        messageForm(R"re(^no "image:" key: not a ROS map_server map$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The YAML file names no image (image:): it is not a ROS "
                                      "map_server map.")),
        messageForm(R"re(^resolution: missing or not a positive size in metres$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The map's resolution is missing or not a positive size in "
                                      "metres.")),
        messageForm(
            R"re(^resolution: (.*) m per cell is not an occupancy map's \(1 mm to 1 m\)$)re",
            QT_TRANSLATE_NOOP("PlannerMessages",
                              "A resolution of %1 m per cell is not an occupancy map's "
                              "(1 mm to 1 m).")),
        messageForm(R"re(^origin: missing \(expected \[x, y, yaw\]\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "The map has no origin [x, y, yaw].")),
        messageForm(R"re(^origin: \[(.*)\] is far outside any map frame$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The map's origin [%1] lies far outside any map frame.")),
        messageForm(R"re(^thresholds: need 0 <= free_thresh < occupied_thresh <= 1$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The map's thresholds must satisfy 0 ≤ free_thresh < "
                                      "occupied_thresh ≤ 1.")),
        messageForm(R"re(^mode: "(.*)" \(expected trinary, scale or raw\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The map's mode “%1” is unknown: it must be trinary, scale "
                                      "or raw.")),
        messageForm(
            R"re(^not a PGM or PBM image \(expected P1, P2, P4 or P5\)$)re",
            QT_TRANSLATE_NOOP("PlannerMessages", "The map image is not a PGM or PBM image.")),
        messageForm(R"re(^PGM (\w+): "(.*)" is not a number$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "In the PGM image's header, %1 “%2” is not a number.")),
        messageForm(R"re(^PGM header: bad size or maxval$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The PGM image's header has a bad size or maximum value.")),
        messageForm(
            R"re(^(PGM|PBM) data truncated(?: or not 0/1)?$)re",
            QT_TRANSLATE_NOOP("PlannerMessages", "The %1 image's data is cut short or damaged.")),
        messageForm(R"re(^GDAL lacks its in-memory drivers$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "This FloorCover lacks GDAL's in-memory drivers: reinstall "
                                      "FloorCover.")),
        messageForm(R"re(^cannot hold the map image in memory$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "The map image does not fit in memory.")),
        messageForm(R"re(^the free space is split into more than (\d+) pieces$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The free floor falls into more than %1 pieces: clean the "
                                      "map more (Clean the map).")),
        messageForm(R"re(^tracing the free space failed: (.*)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "Tracing the free floor failed (%1).")),
        messageForm(R"re(^(?:simplifying|smoothing) the free space failed$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "Smoothing the outline of the free floor failed.")),

        // Assembling, repairing and WKT plans (importers/PlanAssembly.cpp).
        messageForm(R"re(^no free (?:space|area) left to import$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "No free floor is left to import.")),
        messageForm(
            R"re(^(\d+) separate free (?:space|area) parts? \((.*) m2\) not connected to )re"
            R"re(the largest; dropped$)re",
            QT_TRANSLATE_NOOP(
                "PlannerMessages",
                "Pieces of floor not connected to the largest, left out: %1 (%2 m²).")),
        messageForm(R"re(^the obstacles could not be merged \(invalid geometry\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The obstacles could not be merged (their outlines are "
                                      "invalid).")),
        messageForm(R"re(^the obstacles could not be cut out of the boundary$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The obstacles could not be cut out of the outer wall.")),
        messageForm(R"re(^no closed outline for the boundary; (.*) \(a larger gap tolerance may )re"
                    R"re(close them\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "No closed outline for the outer wall; not closed: %1. A "
                                      "larger “Close gaps up to” may close them.")),
        messageForm(R"re(^no closed outline for the boundary$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "No closed outline for the outer wall: give the layer of "
                                      "the walls the role Boundary, or close its gaps with “Close "
                                      "gaps up to”.")),
        messageForm(R"re(^(\d+) closed outlines outside the boundary ignored$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "Closed outlines outside the outer wall, left out: %1.")),
        messageForm(R"re(^(\d+) room outlines outside the boundary ignored$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "Room outlines outside the outer wall, left out: %1.")),
        messageForm(R"re(^the plan has no boundary to repair$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The plan has no outer wall to repair: draw one first.")),
        messageForm(R"re(^the boundary encloses no area$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "The outer wall encloses no area.")),
        messageForm(R"re(^the boundary crossed or touched itself: split where it does$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The outer wall crossed or touched itself: it was split "
                                      "there.")),
        messageForm(R"re(^(\d+) obstacle\(s\) without area removed$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "Obstacles without area, removed: %1.")),
        messageForm(
            R"re(^(\d+) obstacle\(s\) crossed themselves: split where they cross$)re",
            QT_TRANSLATE_NOOP("PlannerMessages",
                              "Obstacles that crossed themselves, split where they cross: %1.")),
        messageForm(
            R"re(^obstacles that touched the wall or each other at a point shrunk by 1 mm$)re",
            QT_TRANSLATE_NOOP("PlannerMessages",
                              "Obstacles that touched the outer wall or each other at a "
                              "single point were shrunk by 1 mm.")),
        messageForm(
            R"re(^obstacles merged, clipped to the boundary or joined to the wall: (\d+) )re"
            R"re(before, (\d+) after$)re",
            QT_TRANSLATE_NOOP("PlannerMessages",
                              "Obstacles were merged, clipped to the outer wall or joined "
                              "to it: %1 before, %2 after.")),
        messageForm(R"re(^{ring} lies outside the floor or under other rooms: removed$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "%1 lay outside the floor or under other rooms and was "
                                      "removed.")),
        messageForm(R"re(^{ring} reshaped to fit the floor \((.*) m2 before, (.*) m2 after\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "%1 was reshaped to fit the floor (%2 m² before, %3 m² "
                                      "after).")),
        messageForm(R"re(^{ring} renamed "(.*)"$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "%1 was renamed “%2”.")),
        messageForm(R"re(^"SRID=" without ";"$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The WKT text begins with SRID= but has no “;” after the "
                                      "code.")),
        messageForm(
            R"re(^SRID is not a number$)re",
            QT_TRANSLATE_NOOP("PlannerMessages", "The SRID of the WKT text is not a number.")),
        messageForm(R"re(^not valid WKT$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "The file is not valid WKT.")),
        messageForm(
            R"re(^text after the WKT geometry$)re",
            QT_TRANSLATE_NOOP("PlannerMessages", "There is more text after the WKT geometry.")),
        messageForm(R"re(^WKT (\S+) is not a POLYGON or MULTIPOLYGON$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The WKT geometry is a %1, not a POLYGON or "
                                      "MULTIPOLYGON.")),
        messageForm(R"re(^the WKT polygon is empty$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "The WKT polygon is empty.")),
        messageForm(R"re(^holes of polygon (\d+) \(a room\) ignored$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The holes of polygon %1 (a room) were left out.")),

        // DXF drawings (importers/DxfImport.cpp, DxfChains.cpp).
        messageForm(
            R"re(^not a readable DXF file \((.*)\)$)re",
            QT_TRANSLATE_NOOP("PlannerMessages", "The file is not a readable DXF drawing (%1).")),
        messageForm(
            R"re(^not a readable DXF file$)re",
            QT_TRANSLATE_NOOP("PlannerMessages", "The file is not a readable DXF drawing.")),
        messageForm(R"re(^more than (\d+) vertices$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The drawing has more than %1 vertices, more than "
                                      "FloorCover imports.")),
        messageForm(R"re(^more than (\d+) open lines$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The drawing has more than %1 open lines, more than "
                                      "FloorCover imports.")),
        messageForm(R"re(^more than (\d+) entities$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The drawing has more than %1 entities, more than "
                                      "FloorCover imports.")),
        messageForm(R"re(^a coordinate on layer "(.*)" is not finite$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "A coordinate on layer “%1” is not a finite number.")),
        messageForm(R"re(^no \$INSUNITS in the header: drawing units taken as metres$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The drawing does not say its unit ($INSUNITS): it was "
                                      "read in metres; correct Units if it is not.")),
        messageForm(R"re(^\$INSUNITS (-?\d+) \(unitless or unknown\): drawing units taken as )re"
                    R"re(metres$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The drawing's unit ($INSUNITS %1) is unitless or unknown: "
                                      "it was read in metres; correct Units if it is not.")),
        messageForm(R"re(^the drawing has no entities$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "The drawing is empty.")),
        messageForm(
            R"re(^layer "(.*)": (\d+) entities ignored$)re",
            QT_TRANSLATE_NOOP("PlannerMessages",
                              "Entities left out on layer “%1” (its role is Ignored): %2.")),
        messageForm(R"re(^(\d+) entities without usable 2D geometry skipped$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "Entities without usable 2D geometry, skipped: %1.")),
        messageForm(
            R"re(^layer "(.*)": (\d+) open segments? \((.*) m\) not closed into an )re"
            R"re(outline; ignored$)re",
            QT_TRANSLATE_NOOP("PlannerMessages",
                              "Open lines on layer “%1” that close into no outline, left out: %2 "
                              "(%3 m); a larger “Close gaps up to” may close them.")),

        // The tiling robot (tiling/TilingRobot.cpp, TilingPlanner.cpp, OrderBaselines.cpp).
        messageForm(R"re(^block leg must be a positive length in metres$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The block leg must be a positive length in metres: change "
                                      "it in the Tiling Robot panel.")),
        messageForm(
            R"re(^the floor needs about (\d+) tiles of a (.*) m block leg, more than (\d+): choose a longer block leg$)re",
            QT_TRANSLATE_NOOP("PlannerMessages",
                              "The floor would need about %1 tiles of a %2 m block leg, "
                              "more than %3: choose a longer block leg.")),
        messageForm(
            R"re(^block masses must be positive and at most 1,000,000 kg$)re",
            QT_TRANSLATE_NOOP("PlannerMessages",
                              "The block masses must be positive, at most 1,000,000 kg: change "
                              "them in the Tiling Robot panel.")),
        messageForm(R"re(^unsupported waypoint file "(.*)" \(use \.csv or \.json\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "Waypoints are exported as .csv or .json files, not as "
                                      "“%1”.")),
        messageForm(
            R"re(^exact ordering is limited to (\d+) waypoints \(this floor has (\d+)\)$)re",
            QT_TRANSLATE_NOOP("PlannerMessages",
                              "The exact ordering handles at most %1 waypoints, and this "
                              "floor has %2: choose another ordering in the Tiling Robot "
                              "panel.")),
        messageForm(
            R"re(^unknown tiling solver "(.*)" \((.*)\)$)re",
            QT_TRANSLATE_NOOP("PlannerMessages", "There is no ordering “%1” (available: %2).")),
    };
}

} // namespace fc::ui::messages

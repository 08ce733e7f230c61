// Shared by the CLI commands: the plan options and how they become a PlanRequest.
#pragma once

#include "Arguments.h"
#include "formats/PathIO.h"
#include "formats/PlanIO.h"
#include "pipeline/Planner.h"

#include <string>
#include <vector>

namespace fc::cli {

extern const std::vector<std::string> kPlanOptions;

// A request from the project file's settings, overridden by command-line options.
PlanRequest requestFrom(const Project& project, const Arguments& args);
// Plans `project` as the options ask, printing warnings and notes on stderr; errors become
// InputError("PATH: problem").
PlanResult planFromArguments(const std::string& path, const Project& project, const Arguments& args,
                             PlanRequest& request);
// Throws e again as "PATH: problem", of the same kind (a RepairablePlanError stays one, so
// that the error can point to the repair).
[[noreturn]] void rethrowInFile(const std::string& path, const InputError& e);
// Solver, robot, metrics and EPSG of a planned path, for the path writers.
PathExportInfo exportInfoFor(const Project& project, const PlanRequest& request,
                             const PlanResult& result);
// The one positional PLAN argument; throws InputError otherwise.
const std::string& planPath(const Arguments& args);
// loadProjectFile, its notes printed on stderr; --building K picks a building of a site.
Project loadProject(const std::string& path, const Arguments& args);

// SitePlanCommand.cpp: `plan SITE` (or --building all), every building of a site in one run.
// areas: the site's buildings' outline areas, largest first (SiteError::buildingAreas; empty:
// a plan of one building, planned as such a site).
int commandPlanSite(const Arguments& args, const std::vector<double>& areas);
// A building's file of a site's: "site.csv" -> "site-building-2.csv".
std::string buildingFile(const std::string& out, int building);
int commandTrain(const Arguments& args);
int commandTile(const Arguments& args);   // TileCommand.cpp: the tiling robot
int commandImport(const Arguments& args); // ImportCommand.cpp: DXF, ROS maps, WKT to a plan
int commandExport(const Arguments& args); // ExportCommand.cpp: files for robots and GIS

} // namespace fc::cli

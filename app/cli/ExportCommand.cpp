// floorcover-cli export: the path, the plan or its zones in the formats robot vendors and
// GIS tools read (formats/Export.h); prints one JSON line describing the file written.
#include "CliCommon.h"
#include "formats/Export.h"
#include "formats/FileIO.h"

#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <utility>

namespace fc::cli {

namespace {

struct Exported {
    std::string format, what;
    size_t bytes = 0;
};

// The format and what is written, from the options and --out's extension; errors name the
// output file.
std::pair<ExportFormat, ExportSubject> formatOf(const Arguments& args, const std::string& out) {
    try {
        std::optional<ExportFormat> format;
        if (auto name = args.text("--format"))
            format = exportFormatNamed(*name);
        else
            format = exportFormatForExtension(out);
        if (!format)
            throw InputError("cannot tell the export format from the file extension; give "
                             "--format (see floorcover-cli --help)");
        const ExportSubject subject = args.has("--what") ? exportSubjectNamed(*args.text("--what"))
                                                         : defaultExportSubject(*format);
        if (!exportSupports(*format, subject))
            throw InputError("--format " + exportFormatName(*format) + " cannot hold --what " +
                             *args.text("--what"));
        return {*format, subject};
    } catch (const InputError& e) {
        throw InputError(out + ": " + e.what());
    }
}

Exported exportOne(const Arguments& args) {
    const std::string& path = planPath(args);
    const std::string out = *args.text("--out");
    const auto [format, subject] = formatOf(args, out);

    const Project project = loadProject(path, args);
    PathExportInfo info;
    CoveragePath coveragePath;
    if (exportNeedsPath(subject)) {
        PlanRequest request;
        const PlanResult result = planFromArguments(path, project, args, request);
        info = exportInfoFor(project, request, result);
        coveragePath = result.path;
    }
    info.epsg = project.plan.epsg;
    info.frameId = args.text("--frame-id").value_or(info.frameId);
    info.manufacturer = args.text("--manufacturer").value_or(info.manufacturer);
    info.serialNumber = args.text("--serial-number").value_or(info.serialNumber);
    info.mapId = args.text("--map-id").value_or(info.mapId);
    info.orderId =
        args.text("--order-id").value_or(std::filesystem::path(path).stem().string() + "-coverage");

    std::string contents;
    try {
        contents = exportToFormat(format, subject, project.plan, coveragePath, info);
    } catch (const InputError& e) {
        throw InputError(path + ": " + e.what());
    }
    if (format == ExportFormat::Wgs84GeoJson && !project.plan.epsg)
        std::cerr << "floorcover-cli: note: " << path
                  << ": the plan has no EPSG code; written in local metres, marked "
                     "\"floorcover:crs\": \"local metres\"\n";
    writeFileAtomically(out, contents);
    const char* what = subject == ExportSubject::Path   ? "path"
                       : subject == ExportSubject::Plan ? "plan"
                                                        : "zones";
    return {exportFormatName(format), what, contents.size()};
}

std::string jsonOf(const Exported& e) {
    return "\"format\":\"" + e.format + "\",\"what\":\"" + e.what +
           "\",\"bytes\":" + std::to_string(e.bytes);
}

// Every building of a site, each to a file of its own ("site.csv" -> "site-building-2.csv"),
// as `plan` writes a site's paths; a building that cannot be exported is left out with a
// warning and a "skipped" entry. One JSON line: the buildings' files, then their total.
int exportSite(const Arguments& args, const std::vector<double>& areas) {
    const std::string& path = planPath(args);
    const std::string out = *args.text("--out");
    std::cerr << "floorcover-cli: note: " << path << ": " << areas.size()
              << " buildings, each exported on its own to NAME-building-K (--building K "
                 "exports one)\n";
    std::string entries;
    size_t bytes = 0, written = 0;
    std::optional<Exported> any;
    for (size_t k = 1; k <= areas.size(); ++k) {
        const std::string file = buildingFile(out, static_cast<int>(k));
        std::string entry = "{\"building\":" + std::to_string(k);
        try {
            Arguments building = args.with("--building", std::to_string(k)).with("--out", file);
            if (!args.has("--order-id")) // a VDA 5050 order per building
                building =
                    building.with("--order-id", std::filesystem::path(path).stem().string() +
                                                    "-building-" + std::to_string(k) + "-coverage");
            const Exported e = exportOne(building);
            entry += ",\"file\":" + nlohmann::json(file).dump() + "," + jsonOf(e) + "}";
            bytes += e.bytes;
            ++written;
            any = e;
        } catch (const InputError& e) {
            std::cerr << "floorcover-cli: warning: " << path << ": building " << k
                      << " not exported: " << e.what() << "\n";
            entry += ",\"skipped\":" + nlohmann::json(std::string(e.what())).dump() + "}";
        }
        entries += (entries.empty() ? "" : ",") + entry;
    }
    if (!any)
        throw InputError(path + ": no building of the site could be exported");
    std::cout << "{\"format\":\"" << any->format << "\",\"what\":\"" << any->what
              << "\",\"bytes\":" << bytes << ",\"files\":" << written << ",\"buildings\":["
              << entries << "]}" << std::endl;
    return written == areas.size() || !args.has("--strict") ? 0 : 3;
}

} // namespace

int commandExport(const Arguments& args) {
    std::vector<std::string> allowed = kPlanOptions;
    for (const char* option : {"--format", "--what", "--frame-id", "--manufacturer",
                               "--serial-number", "--order-id", "--map-id"})
        allowed.push_back(option);
    args.allowOnly(allowed);
    const std::string& path = planPath(args);
    if (!args.text("--out"))
        throw InputError(path + ": export needs --out FILE");
    formatOf(args, *args.text("--out")); // option errors first, once for a whole site
    // A site without --building (or with --building all): every building.
    if (!args.has("--building") || args.text("--building") == "all") {
        std::vector<double> areas;
        try {
            loadProjectFile(path);
        } catch (const SiteError& e) {
            areas = e.buildingAreas();
        } catch (const InputError&) {
            // reported below, after the options, as for one building
        }
        if (areas.size() > 1)
            return exportSite(args.with("--building", std::nullopt), areas);
        if (args.has("--building"))
            return commandExport(args.with("--building", std::nullopt));
    }
    const Exported exported = exportOne(args);
    std::cout << "{" << jsonOf(exported) << "}" << std::endl;
    return 0;
}

} // namespace fc::cli

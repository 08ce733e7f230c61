// floorcover-cli export: the path, the plan or its zones in the formats robot vendors and
// GIS tools read (formats/Export.h); prints one JSON line describing the file written.
#include "CliCommon.h"
#include "formats/Export.h"
#include "formats/FileIO.h"

#include <filesystem>
#include <iostream>

namespace fc::cli {

int commandExport(const Arguments& args) {
    std::vector<std::string> allowed = kPlanOptions;
    for (const char* option : {"--format", "--what", "--frame-id", "--manufacturer",
                               "--serial-number", "--order-id", "--map-id"})
        allowed.push_back(option);
    args.allowOnly(allowed);
    const std::string& path = planPath(args);
    const auto out = args.text("--out");
    if (!out)
        throw InputError(path + ": export needs --out FILE");
    std::optional<ExportFormat> format;
    ExportSubject subject = ExportSubject::Path;
    try { // option errors name the output file
        if (auto name = args.text("--format"))
            format = exportFormatNamed(*name);
        else
            format = exportFormatForExtension(*out);
        if (!format)
            throw InputError("cannot tell the export format from the file extension; give "
                             "--format (see floorcover-cli --help)");
        subject = args.has("--what") ? exportSubjectNamed(*args.text("--what"))
                                     : defaultExportSubject(*format);
        if (!exportSupports(*format, subject))
            throw InputError("--format " + exportFormatName(*format) + " cannot hold --what " +
                             *args.text("--what"));
    } catch (const InputError& e) {
        throw InputError(*out + ": " + e.what());
    }

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
        contents = exportToFormat(*format, subject, project.plan, coveragePath, info);
    } catch (const InputError& e) {
        throw InputError(path + ": " + e.what());
    }
    if (*format == ExportFormat::Wgs84GeoJson && !project.plan.epsg)
        std::cerr << "floorcover-cli: note: " << path
                  << ": the plan has no EPSG code; written in local metres, marked "
                     "\"floorcover:crs\": \"local metres\"\n";
    writeFileAtomically(*out, contents);
    const char* what = subject == ExportSubject::Path   ? "path"
                       : subject == ExportSubject::Plan ? "plan"
                                                        : "zones";
    std::cout << "{\"format\":\"" << exportFormatName(*format) << "\",\"what\":\"" << what
              << "\",\"bytes\":" << contents.size() << "}" << std::endl;
    return 0;
}

} // namespace fc::cli

// File > Export through the window's API (the menus' dialog-free entry points): every path
// format, the zones and the WGS84 plan land in files that parse back to the planned path.
#include "EditorFixture.h"
#include "formats/Export.h"
#include "formats/FileIO.h"
#include "formats/PlanIO.h"
#include "tasks/PlanningController.h"

#include <QStandardPaths>
#include <QTemporaryDir>
#include <nlohmann/json.hpp>
#include <sstream>

using namespace fc::ui;
using namespace fc::ui::test;
using nlohmann::json;

class ExportTest : public QObject {
    Q_OBJECT

private:
    QTemporaryDir dir_;
    QString file(const char* name) const { return dir_.filePath(QLatin1String(name)); }
    static std::string text(const QString& path) { return fc::readFile(path.toStdString()); }

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(dir_.isValid());
    }

    void exportsEveryFormatFromTheWindow() {
        auto window = makeWindow();
        QVERIFY(window->openFile(QStringLiteral(FC_PLANS_DIR "/room-obstacle.geojson")));
        // Zones and the plan need no path; the path exports refuse until planned.
        QVERIFY2(window->exportFile(file("zones.json"), fc::ExportFormat::Zones,
                                    fc::ExportSubject::Zones),
                 qPrintable(window->lastError()));
        QVERIFY(window->exportFile(file("plan.geojson"), fc::ExportFormat::Wgs84GeoJson,
                                   fc::ExportSubject::Plan));
        QVERIFY(
            window->exportFile(file("plan.wkt"), fc::ExportFormat::Wkt, fc::ExportSubject::Plan));
        QVERIFY(!window->exportFile(file("order.json"), fc::ExportFormat::Vda5050,
                                    fc::ExportSubject::Path));
        QVERIFY(window->planningController()->planAndWait());
        const auto result = window->planningController()->result();
        QVERIFY(result && result->path.points.size() > 10);

        const json zones = json::parse(text(file("zones.json")));
        QCOMPARE(zones.at("units").get<std::string>(), std::string("m"));
        QCOMPARE(zones.at("zones").size(),
                 std::max<size_t>(1, window->document()->plan().rooms.size()));
        const json plan = json::parse(text(file("plan.geojson")));
        QCOMPARE(plan.at("floorcover:crs").get<std::string>(), std::string("local metres"));
        QVERIFY(text(file("plan.wkt")).rfind("POLYGON", 0) != std::string::npos);

        using F = fc::ExportFormat;
        const std::vector<std::pair<const char*, F>> formats = {
            {"path.geojson", F::GeoJson}, {"path.csv", F::Csv},   {"path.json", F::Json},
            {"path.yaml", F::RosPath},    {"nav2.yaml", F::Nav2}, {"path.txt", F::Fields2Cover},
            {"order.json", F::Vda5050},   {"path.wkt", F::Wkt},   {"path.svg", F::Svg},
            {"path.pdf", F::Pdf}};
        for (const auto& [name, format] : formats)
            QVERIFY2(window->exportFile(file(name), format, fc::ExportSubject::Path),
                     qPrintable(window->lastError()));

        // The VDA 5050 nodes and the JSON waypoints are the planned path's distinct points.
        const json order = json::parse(text(file("order.json")));
        const json waypoints = json::parse(text(file("path.json"))).at("waypoints");
        QCOMPARE(waypoints.size(), result->path.points.size());
        QVERIFY(order.at("nodes").size() >= 2 && order.at("nodes").size() <= waypoints.size());
        QCOMPARE(order.at("nodes")[0].at("nodePosition").at("x").get<double>(),
                 result->path.points.front().x);
        QCOMPARE(order.at("edges").size(), order.at("nodes").size() - 1);
        // Fields2Cover: one eight-number state per distinct segment, then the units line.
        std::istringstream f2c(text(file("path.txt")));
        double values[8];
        size_t states = 0;
        while (f2c >> values[0] >> values[1] >> values[2] >> values[3] >> values[4] >> values[5] >>
               values[6] >> values[7])
            ++states;
        QCOMPARE(states, order.at("edges").size());
        QVERIFY(text(file("nav2.yaml")).find("orientation: {x: 0.0, y: 0.0, z: ") !=
                std::string::npos);
        QVERIFY(text(file("path.pdf")).rfind("%PDF-1.4", 0) == 0);
        QVERIFY(text(file("path.svg")).find("<svg") != std::string::npos);
        // exportPath picks the format from the extension, as before.
        QVERIFY(window->exportPath(file("again.csv")));
        QVERIFY(text(file("again.csv")) == text(file("path.csv")));
        QVERIFY(!window->exportPath(file("path.unknown")));
    }
};

QTEST_MAIN(ExportTest)
#include "test_export.moc"

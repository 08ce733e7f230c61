// floorcover: the desktop editor. Thin: argument handling only; the editor lives in
// the floorcover_widgets library.
#include "learning/dqn/DqnSolver.h"
#include "tiling/ppo/PpoOrdering.h"
#include "window/MainWindow.h"
#include "window/Translations.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QIcon>
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <optional>

namespace {

// `--screenshot` needs no display: without one (and without a platform chosen by the
// user) it renders offscreen instead of failing to connect.
void preferOffscreenForScreenshots(int argc, char** argv) {
    const bool screenshot = std::any_of(argv + 1, argv + argc, [](const char* arg) {
        return std::strncmp(arg, "--screenshot", 12) == 0;
    });
    if (screenshot && qEnvironmentVariableIsEmpty("DISPLAY") &&
        qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY") &&
        qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
}

} // namespace

int main(int argc, char** argv) {
    preferOffscreenForScreenshots(argc, argv);
    QApplication app(argc, argv);
    fc::registerDqnSolver(); // before the window lists the solvers
    fc::registerPpoOrdering();
    QApplication::setOrganizationName(QStringLiteral("FloorCover"));
    QApplication::setApplicationName(QStringLiteral("FloorCover"));
    QApplication::setApplicationVersion(QStringLiteral(FC_VERSION));
    QApplication::setWindowIcon(QIcon(QStringLiteral(":/icons/floorcover.svg")));
    QApplication::setDesktopFileName(QStringLiteral("floorcover"));
    fc::ui::installTranslations(app);

    QCommandLineParser parser;
    parser.setApplicationDescription(
        QApplication::translate("main", "Coverage path planning for floor plans"));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption screenshot(
        QStringLiteral("screenshot"),
        QApplication::translate("main",
                                "Render the main window with overlays and a planned path to "
                                "FILE (PNG) and exit."),
        QApplication::translate("main", "FILE"));
    parser.addOption(screenshot);
    const QCommandLineOption building(
        QStringLiteral("building"),
        QApplication::translate("main", "Of a GeoJSON site of several buildings, open building K "
                                        "(1 = the largest) instead of asking."),
        QStringLiteral("K"));
    parser.addOption(building);
    parser.addPositionalArgument(QStringLiteral("plan"),
                                 QApplication::translate("main", "A .fcproj or .geojson file."),
                                 QStringLiteral("[PLAN]"));
    parser.process(app);
    const QStringList positional = parser.positionalArguments();
    const QString planPath = positional.value(0);
    std::optional<int> buildingNumber;
    if (parser.isSet(building)) {
        bool ok = false;
        const int k = parser.value(building).toInt(&ok);
        if (!ok || k < 1) {
            std::fprintf(stderr, "floorcover: --building %s: buildings are numbered from 1\n",
                         qPrintable(parser.value(building)));
            return 2;
        }
        buildingNumber = k;
    }

    fc::ui::MainWindow window;
    if (parser.isSet(screenshot)) {
        QString error;
        if (!window.renderScreenshot(parser.value(screenshot), planPath, &error, buildingNumber)) {
            std::fprintf(stderr, "floorcover: %s\n", qPrintable(error));
            return 2;
        }
        return 0;
    }
    window.show();
    // A plan named on the command line, else what a crashed session left, else the sample.
    if (!planPath.isEmpty() && window.openFile(planPath, buildingNumber))
        return QApplication::exec();
    if (!window.recoverAutosave()) {
        window.openSample();
        window.showWelcomeAtStart(); // a first start: the samples and the ways to begin
    }
    return QApplication::exec();
}

// Plain language and help (issue 16, item 3): every control explains itself in a tooltip,
// the planner's messages reach the window in the editor's words and translated, Qt's own
// dialogs speak the user's language, a welcome page offers the samples and a Getting
// Started page is in the Help menu.
#include "EditorFixture.h"
#include "dialogs/CompareDialog.h"
#include "dialogs/ImportDialog.h"
#include "dialogs/PreferencesDialog.h"
#include "docks/ProblemsDock.h"
#include "document/PlannerMessages.h"
#include "model/Validation.h"
#include "window/HelpDialog.h"
#include "window/SamplePlans.h"
#include "window/Translations.h"
#include "window/WelcomeDialog.h"

#include <QAbstractButton>
#include <QAbstractSpinBox>
#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QFile>
#include <QLibraryInfo>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSettings>
#include <QSlider>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTextBrowser>
#include <QTranslator>

using namespace fc::ui;
using namespace fc::ui::test;

namespace {

// Controls a person clicks or types into that say nothing when hovered.
QStringList controlsWithoutTooltip(QWidget* root) {
    QStringList missing;
    for (QWidget* w : root->findChildren<QWidget*>()) {
        const bool control = qobject_cast<QAbstractButton*>(w) ||
                             qobject_cast<QAbstractSpinBox*>(w) || qobject_cast<QComboBox*>(w) ||
                             qobject_cast<QLineEdit*>(w) || qobject_cast<QSlider*>(w) ||
                             qobject_cast<QListWidget*>(w) || qobject_cast<QTableWidget*>(w);
        if (!control || qobject_cast<QLineEdit*>(w->parentWidget()) ||
            qobject_cast<QAbstractSpinBox*>(w->parentWidget()) ||
            qobject_cast<QComboBox*>(w->parentWidget()))
            continue; // the editor inside a spin box or combo box
        // Dock title buttons, scroll bar parts and tab bar scrollers are Qt's own.
        if (w->inherits("QDockWidgetTitleButton") || w->inherits("QToolBarExtension") ||
            w->objectName().startsWith(QLatin1String("qt_")) || w->inherits("QTabBar") ||
            w->parentWidget()->inherits("QTabBar") || w->inherits("QTableCornerButton"))
            continue;
        // OK and Cancel of a dialog's button box say what they do.
        if (auto* button = qobject_cast<QAbstractButton*>(w);
            button && qobject_cast<QDialogButtonBox*>(w->parentWidget())) {
            const auto role =
                static_cast<QDialogButtonBox*>(w->parentWidget())->standardButton(button);
            if (role == QDialogButtonBox::Ok || role == QDialogButtonBox::Cancel)
                continue;
        }
        if (w->toolTip().isEmpty()) {
            QString name = QString::fromLatin1(w->metaObject()->className());
            if (auto* b = qobject_cast<QAbstractButton*>(w))
                name += QStringLiteral(" \"") + b->text() + QLatin1Char('"');
            if (!w->objectName().isEmpty())
                name += QStringLiteral(" #") + w->objectName();
            for (QWidget* p = w->parentWidget(); p; p = p->parentWidget())
                if (auto* dock = qobject_cast<QDockWidget*>(p)) {
                    name += QStringLiteral(" in ") + dock->windowTitle();
                    break;
                }
            missing << name;
        }
    }
    return missing;
}

} // namespace

class HelpTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void everyControlHasATooltip() {
        auto window = makeWindow();
        window->openSample();
        QVERIFY(window->planningController() != nullptr);
        QStringList missing = controlsWithoutTooltip(window.get());
        // The dialogs too.
        CompareDialog compare(fc::planRequestFor(window->document()->project()));
        missing += controlsWithoutTooltip(&compare);
        PreferencesDialog preferences;
        missing += controlsWithoutTooltip(&preferences);
        ImportDialog import(QStringLiteral(FC_PLANS_DIR "/office.geojson"));
        missing += controlsWithoutTooltip(&import);
        for (const QString& control : missing)
            qWarning("no tooltip: %s", qPrintable(control));
        QVERIFY2(missing.isEmpty(), "controls without a tooltip (listed above)");
    }

    void welcomePageOffersTheSamplesAndOpensThem() {
        auto window = makeWindow();
        window->showWelcome();
        auto* welcome = window->findChild<WelcomeDialog*>();
        QVERIFY(welcome);
        QVERIFY(welcome->isVisible());
        QCOMPARE(welcome->samples()->count(), int(samplePlans().size()));
        QVERIFY(samplePlans().size() >= 6);
        for (const SamplePlan& sample : samplePlans())
            QVERIFY2(QFile::exists(sample.path), qPrintable(sample.path));
        welcome->samples()->setCurrentRow(1); // the ward
        QPushButton* open = nullptr;
        for (QPushButton* b : welcome->findChildren<QPushButton*>())
            if (b->text() == QStringLiteral("Open Sample"))
                open = b;
        QVERIFY(open);
        open->click();
        QCOMPARE(window->document()->displayName(), QStringLiteral("ward"));
        QTRY_VERIFY(!window->findChild<WelcomeDialog*>() ||
                    !window->findChild<WelcomeDialog*>()->isVisible());
        // Shown at start until turned off.
        QSettings().remove(QStringLiteral("welcome/show"));
        QVERIFY(WelcomeDialog::showAtStart());
        WelcomeDialog again;
        again.findChild<QCheckBox*>()->setChecked(false);
        QVERIFY(!WelcomeDialog::showAtStart());
        QSettings().remove(QStringLiteral("welcome/show"));
    }

    void gettingStartedIsInTheHelpMenuAndTranslated() {
        auto window = makeWindow();
        QAction* guide = window->findChild<QAction*>(QStringLiteral("gettingStarted"));
        QVERIFY(guide);
        QCOMPARE(guide->shortcut(), QKeySequence(QKeySequence::HelpContents));
        guide->trigger();
        auto* help = window->findChild<HelpDialog*>();
        QVERIFY(help);
        const QString text = help->browser()->toPlainText();
        QVERIFY2(text.contains(QStringLiteral("Getting started")), qPrintable(text.left(200)));
        QVERIFY(text.contains(QStringLiteral("Repair Plan")));
        QVERIFY(
            HelpDialog::pagePath(QLocale(QLocale::German)).endsWith(QStringLiteral("_de.html")));
        QVERIFY(
            HelpDialog::pagePath(QLocale(QLocale::French)).endsWith(QStringLiteral("_fr.html")));
        QCOMPARE(HelpDialog::pagePath(QLocale(QLocale::Spanish)),
                 QStringLiteral(":/help/getting-started.html"));
        QFile german(HelpDialog::pagePath(QLocale(QLocale::German)));
        QVERIFY(german.open(QIODevice::ReadOnly));
        QVERIFY(QString::fromUtf8(german.readAll()).contains(QStringLiteral("Erste Schritte")));
    }

    void qtsOwnDialogsAreTranslated() {
        for (QLocale::Language language : {QLocale::German, QLocale::French}) {
            QTranslator qt;
            QVERIFY2(loadQtTranslation(qt, QLocale(language)),
                     "Qt's translations are missing (qt6-translations-l10n)");
            QCoreApplication::installTranslator(&qt);
            const QString open = QCoreApplication::translate("QFileDialog", "&Open");
            const QString cancel = QCoreApplication::translate("QPlatformTheme", "Cancel");
            QCoreApplication::removeTranslator(&qt);
            QVERIFY2(open != QStringLiteral("&Open"), qPrintable(open));
            QVERIFY2(cancel != QStringLiteral("Cancel"), qPrintable(cancel));
        }
    }

    // What the planner says reaches the window in the editor's words, and translated.
    void plannerMessagesAreSaidInTheEditorsWords() {
        fc::Plan plan;
        plan.boundary = {{0, 0}, {20, 0}, {20, 10}, {0, 10}};
        plan.obstacles = {{{-1, 4}, {2, 4}, {2, 6}, {-1, 6}},
                          {{8, 2}, {12, 2}, {12, 5}, {8, 5}},
                          {{10, 3}, {14, 3}, {14, 7}, {10, 7}}};
        plan.rooms = {{"A", {{0, 0}, {12, 0}, {12, 10}, {0, 10}}},
                      {"B", {{8, 0}, {20, 0}, {20, 10}, {8, 10}}}};
        QStringList messages;
        for (const fc::PlanProblem& problem : fc::planProblems(plan, fc::RobotProfile{}))
            messages << QString::fromStdString(problem.message);
        fc::Plan bowTie;
        bowTie.boundary = {{0, 0}, {10, 8}, {10, 0}, {0, 8}};
        for (const fc::PlanProblem& problem : fc::planProblems(bowTie, fc::RobotProfile{}))
            messages << QString::fromStdString(problem.message);
        fc::Plan rooms;
        rooms.boundary = plan.boundary;
        rooms.rooms = plan.rooms;
        for (const fc::PlanProblem& problem : fc::planProblems(rooms, fc::RobotProfile{}))
            messages << QString::fromStdString(problem.message);
        fc::RobotProfile robot;
        robot.robotDiameter = 2.0;
        try {
            robot.validate();
        } catch (const fc::InputError& e) {
            messages << QString::fromStdString(e.what());
        }
        // Forms the plans above do not reach, as the validator words them.
        messages << QStringLiteral("obstacles 2 and 5 are identical (duplicate obstacle)")
                 << QStringLiteral("room 3 has no name")
                 << QStringLiteral("room \"Store\" does not overlap the free space (it covers "
                                   "only obstacles)")
                 << QStringLiteral("free area 0.12 m^2 (boundary minus obstacles) is smaller "
                                   "than the robot footprint 0.28 m^2 (L = 0.6 m)");
        QVERIFY(messages.size() >= 9);
        QTranslator german;
        QVERIFY(loadEditorTranslation(german, QLocale(QLocale::German)));
        for (const QString& message : messages) {
            const QString plain = plainMessage(message);
            QVERIFY2(plain != message, qPrintable(QStringLiteral("not reworded: ") + message));
            QVERIFY2(!plain.contains(QStringLiteral("--")), qPrintable(plain));
            QCoreApplication::installTranslator(&german);
            const QString translated = plainMessage(message);
            QCoreApplication::removeTranslator(&german);
            QVERIFY2(translated != plain, qPrintable(QStringLiteral("not translated: ") + plain));
        }
    }
};

QTEST_MAIN(HelpTest)
#include "test_help.moc"

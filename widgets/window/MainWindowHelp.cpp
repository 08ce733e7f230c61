// The Help menu: the welcome page, the Getting Started guide and About.
#include "window/HelpDialog.h"
#include "window/MainWindow.h"
#include "window/WelcomeDialog.h"

#include <QApplication>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>

namespace fc::ui {

void MainWindow::createHelpMenu() {
    QMenu* help = menuBar()->addMenu(tr("&Help"));
    QAction* guide = help->addAction(tr("&Getting Started"), this, &MainWindow::showHelp);
    guide->setShortcut(QKeySequence::HelpContents);
    guide->setObjectName(QStringLiteral("gettingStarted"));
    guide->setToolTip(tr("A short guide through a first plan"));
    QAction* welcome = help->addAction(tr("&Welcome Page"), this, &MainWindow::showWelcome);
    welcome->setObjectName(QStringLiteral("welcomePage"));
    welcome->setToolTip(tr("The sample plans and the ways to start"));
    help->addSeparator();
    help->addAction(tr("&About FloorCover"), this, [this]() {
        QMessageBox::about(this, tr("About FloorCover"),
                           tr("FloorCover %1\nCoverage path planning for cleaning and "
                              "disinfection robots.")
                               .arg(QApplication::applicationVersion()));
    });
}

void MainWindow::showWelcome() {
    if (auto* open = findChild<WelcomeDialog*>()) {
        open->raise();
        open->activateWindow();
        return;
    }
    auto* dialog = new WelcomeDialog(this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &WelcomeDialog::sampleChosen, this, [this](const QString& path) {
        if (maybeSave())
            openSample(path);
    });
    connect(dialog, &WelcomeDialog::newFloorChosen, this, [this]() {
        if (maybeSave())
            newDocument();
    });
    connect(dialog, &WelcomeDialog::importChosen, this, &MainWindow::importWithDialog);
    connect(dialog, &WelcomeDialog::openChosen, this, &MainWindow::openWithDialog);
    connect(dialog, &WelcomeDialog::helpChosen, this, &MainWindow::showHelp);
    dialog->show();
}

void MainWindow::showWelcomeAtStart() {
    if (dialogsEnabled_ && WelcomeDialog::showAtStart())
        showWelcome();
}

void MainWindow::showHelp() {
    if (auto* open = findChild<HelpDialog*>()) {
        open->raise();
        open->activateWindow();
        return;
    }
    auto* dialog = new HelpDialog(this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->show();
}

} // namespace fc::ui

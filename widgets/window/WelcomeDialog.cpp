#include "window/WelcomeDialog.h"

#include "window/SamplePlans.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QGridLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSettings>
#include <QVBoxLayout>

namespace fc::ui {

namespace {
const char* const kShowKey = "welcome/show";
}

bool WelcomeDialog::showAtStart() {
    return QSettings().value(QLatin1String(kShowKey), true).toBool();
}

WelcomeDialog::WelcomeDialog(QWidget* parent)
    : QDialog(parent), samples_(new QListWidget(this)),
      showAtStart_(new QCheckBox(tr("Show this page at start"), this)) {
    setWindowTitle(tr("Welcome to FloorCover"));
    setObjectName(QStringLiteral("WelcomeDialog"));
    auto* intro = new QLabel(
        tr("<h2>Welcome to FloorCover</h2>"
           "<p>FloorCover plans the path a cleaning or disinfection robot drives to cover "
           "a floor:</p>"
           "<ol><li><b>Bring a floor plan</b>: draw it, import a CAD drawing or the robot's "
           "map, or try a sample below.</li>"
           "<li><b>Choose the rooms</b> to clean and where the robot starts.</li>"
           "<li><b>Check the path</b> and its time, then export it for the robot or print a "
           "report.</li></ol>"),
        this);
    intro->setWordWrap(true);
    intro->setTextFormat(Qt::RichText);

    samples_->setObjectName(QStringLiteral("welcomeSamples"));
    samples_->setToolTip(tr("Double-click a sample to open it"));
    for (const SamplePlan& sample : samplePlans()) {
        auto* item = new QListWidgetItem(sample.title + QStringLiteral(" — ") + sample.description,
                                         samples_);
        item->setData(Qt::UserRole, sample.path);
    }
    samples_->setCurrentRow(0);
    auto* openSample = new QPushButton(tr("Open Sample"), this);
    openSample->setToolTip(tr("Open the selected sample plan"));

    const auto button = [this](const QString& text, const QString& tip) {
        auto* b = new QPushButton(text, this);
        b->setToolTip(tip);
        return b;
    };
    QPushButton* draw =
        button(tr("Draw a New Floor"), tr("Start an empty drawing with the Draw Boundary tool"));
    QPushButton* import = button(tr("Import a Drawing or Map…"),
                                 tr("DXF drawings, the robot's occupancy map (.yaml), WKT, "
                                    "GeoJSON or 3D building models"));
    QPushButton* open = button(tr("Open a Project…"), tr("Open a saved .fcproj or .geojson"));
    QPushButton* help =
        button(tr("Getting Started"), tr("A short guide through a first plan (F1)"));
    showAtStart_->setChecked(showAtStart());
    showAtStart_->setToolTip(tr("Help > Welcome Page shows it again at any time"));

    auto* starts = new QGridLayout;
    starts->addWidget(draw, 0, 0);
    starts->addWidget(import, 0, 1);
    starts->addWidget(open, 1, 0);
    starts->addWidget(help, 1, 1);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    buttons->button(QDialogButtonBox::Close)->setToolTip(tr("Close this page"));
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addWidget(new QLabel(tr("<b>Sample plans</b>"), this));
    layout->addWidget(samples_, 1);
    layout->addWidget(openSample, 0, Qt::AlignRight);
    layout->addLayout(starts);
    layout->addWidget(showAtStart_);
    layout->addWidget(buttons);
    resize(560, 560);

    const auto chooseSample = [this]() {
        if (QListWidgetItem* item = samples_->currentItem()) {
            emit sampleChosen(item->data(Qt::UserRole).toString());
            accept();
        }
    };
    connect(samples_, &QListWidget::itemDoubleClicked, this, chooseSample);
    connect(openSample, &QPushButton::clicked, this, chooseSample);
    const auto closeWith = [this](void (WelcomeDialog::*signal)()) {
        return [this, signal]() {
            accept();
            emit(this->*signal)();
        };
    };
    connect(draw, &QPushButton::clicked, this, closeWith(&WelcomeDialog::newFloorChosen));
    connect(import, &QPushButton::clicked, this, closeWith(&WelcomeDialog::importChosen));
    connect(open, &QPushButton::clicked, this, closeWith(&WelcomeDialog::openChosen));
    connect(help, &QPushButton::clicked, this, &WelcomeDialog::helpChosen);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(showAtStart_, &QCheckBox::toggled, this,
            [](bool on) { QSettings().setValue(QLatin1String(kShowKey), on); });
}

} // namespace fc::ui

// The sample plans embedded in the program (resources/plans), for File > Open Sample and
// the welcome page.
#pragma once

#include <QList>
#include <QString>

namespace fc::ui {

struct SamplePlan {
    QString path;        // ":/plans/office.geojson"
    QString title;       // translated
    QString description; // translated, one line
};

QList<SamplePlan> samplePlans();

} // namespace fc::ui

#include "window/SamplePlans.h"

#include <QCoreApplication>

namespace fc::ui {

QList<SamplePlan> samplePlans() {
    const auto tr = [](const char* text) {
        return QCoreApplication::translate("fc::ui::SamplePlans", text);
    };
    return {
        {QStringLiteral(":/plans/office.geojson"), tr("Office floor"),
         tr("Twelve offices along a corridor")},
        {QStringLiteral(":/plans/ward.geojson"), tr("Hospital ward"),
         tr("Sixteen patient rooms with beds and a corridor")},
        {QStringLiteral(":/plans/room-obstacle.geojson"), tr("Room with a pillar"),
         tr("One room with an obstacle in it")},
        {QStringLiteral(":/plans/room-notches.geojson"), tr("Room with notches"),
         tr("One room whose walls have recesses")},
        {QStringLiteral(":/plans/simple-diamond.geojson"), tr("Slanted room"),
         tr("A room drawn at an angle, with an obstacle")},
        {QStringLiteral(":/plans/simple.geojson"), tr("Simple room"),
         tr("The smallest example: one room, one obstacle")},
    };
}

} // namespace fc::ui

// Document edits that reshape rooms as a whole: merge two, split one (issue 15: the rooms a
// map's segmentation finds are corrected here). One undoable command each.
#include "document/Conversions.h"
#include "document/Document.h"
#include "document/PlannerMessages.h"
#include "model/RoomEdits.h"

#include <algorithm>

namespace fc::ui {

bool Document::mergeRooms(int first, int second) {
    const int rooms = polygonCount(PolygonRole::Room);
    if (first < 0 || second < 0 || first >= rooms || second >= rooms || first == second)
        return reject(tr("Choose two different rooms to merge."));
    Project changed = project_;
    std::vector<Room>& list = changed.plan.rooms;
    const std::string keep = list[first].name, gone = list[second].name;
    try {
        list[first].outline = mergedRoomOutline(list[first].outline, list[second].outline);
    } catch (const InputError& e) {
        return reject(tr("%1 and %2 cannot be merged: %3")
                          .arg(fromStd(keep), fromStd(gone), plainMessage(fromStd(e.what()))));
    }
    list.erase(list.begin() + second);
    // Planned when either was; the merged room sweeps at the first room's fixed angle.
    auto& selected = changed.selectedRooms;
    const bool wasSelected = std::find(selected.begin(), selected.end(), gone) != selected.end();
    selected.erase(std::remove(selected.begin(), selected.end(), gone), selected.end());
    if (wasSelected && std::find(selected.begin(), selected.end(), keep) == selected.end())
        selected.push_back(keep);
    changed.sweep.roomAngles.erase(gone);
    return pushChange(changed, GeometryChange | RoomsChange | SweepChange,
                      tr("Merge rooms %1 and %2").arg(fromStd(keep), fromStd(gone)));
}

bool Document::splitRoom(int index, Vec2 from, Vec2 to) {
    if (index < 0 || index >= polygonCount(PolygonRole::Room))
        return reject(tr("There is no room %1.").arg(index + 1));
    Project changed = project_;
    std::vector<Room>& list = changed.plan.rooms;
    const std::string name = list[index].name;
    std::pair<Ring, Ring> parts;
    try {
        parts = splitRoomOutline(list[index].outline, from, to);
    } catch (const InputError& e) {
        return reject(
            tr("%1 cannot be split: %2").arg(fromStd(name), plainMessage(fromStd(e.what()))));
    }
    // The larger part keeps the name (and the room's place in the planning order).
    if (ringArea(parts.second) > ringArea(parts.first))
        std::swap(parts.first, parts.second);
    const std::string added = uniqueRoomName().toStdString();
    list[index].outline = std::move(parts.first);
    list.insert(list.begin() + index + 1, Room{added, std::move(parts.second)});
    auto& selected = changed.selectedRooms;
    if (std::find(selected.begin(), selected.end(), name) != selected.end())
        selected.push_back(added);
    if (auto it = changed.sweep.roomAngles.find(name); it != changed.sweep.roomAngles.end())
        changed.sweep.roomAngles[added] = it->second;
    return pushChange(changed, GeometryChange | RoomsChange | SweepChange,
                      tr("Split room %1 (new room %2)").arg(fromStd(name), fromStd(added)));
}

} // namespace fc::ui

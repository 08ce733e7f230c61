#include "document/Document.h"

#include "document/Conversions.h"
#include "document/PlannerMessages.h"
#include "document/ProjectChangeCommand.h"
#include "importers/Import.h"
#include "model/Validation.h"

#include <QFileInfo>
#include <QUndoStack>
#include <algorithm>

namespace fc::ui {

namespace {

const char* const kFloorRoom = "Floor"; // the planner's name for a plan without rooms
// Command ids for QUndoStack merging (ProjectChangeCommand::id()).
constexpr int kSweepMergeId = 1;
constexpr int kRobotMergeId = 10; // + the field's index

std::vector<std::string>::iterator findName(std::vector<std::string>& names,
                                            const std::string& name) {
    return std::find(names.begin(), names.end(), name);
}

} // namespace

Document::Document(Project project, QObject* parent)
    : QObject(parent), project_(std::move(project)), undoStack_(new QUndoStack(this)) {
    connect(undoStack_, &QUndoStack::cleanChanged, this,
            [this](bool clean) { emit modifiedChanged(!clean); });
    updateProblems();
}

void Document::updateProblems() {
    problems_.clear();
    if (project_.plan.boundary.empty())
        return;
    // The plan's own defects: a robot too large for the floor is the robot's problem (the
    // planner says so), not a reason to lock the plan. Nearly every plan is valid, and one
    // validation says so; only a broken one pays for listing all its problems.
    const Plan plan = normalizedPlan(project_.plan);
    try {
        validatePlan(plan, RobotProfile{});
    } catch (const InputError&) {
        problems_ = planProblems(plan, RobotProfile{});
    }
}

bool Document::repair(QStringList* notes) {
    if (!needsRepair())
        return true;
    Project changed = project_;
    std::vector<std::string> changes;
    try {
        changed.plan = normalizedPlan(repairPlan(project_.plan, changes));
    } catch (const InputError& e) {
        return reject(tr("The plan cannot be repaired automatically: %1")
                          .arg(plainMessage(fromStd(e.what()))));
    }
    const QString problem = validationMessage(changed.plan);
    if (!problem.isEmpty())
        return reject(tr("The automatic repair left a problem: %1").arg(problem));
    // Rooms renamed or removed by the repair leave the selection.
    std::vector<std::string> selected;
    for (const std::string& name : changed.selectedRooms)
        for (const Room& room : changed.plan.rooms)
            if (room.name == name)
                selected.push_back(name);
    changed.selectedRooms = selected;
    const auto inFree = [&](Vec2 p) {
        return pointInRing(changed.plan.boundary, p) &&
               std::none_of(changed.plan.obstacles.begin(), changed.plan.obstacles.end(),
                            [&](const Ring& o) { return pointInRing(o, p); });
    };
    if (changed.hasStart && !inFree(changed.start))
        changed.hasStart = false;
    if (changed.hasEnd && !inFree(changed.end))
        changed.hasEnd = false;
    if (notes) {
        notes->clear();
        for (const std::string& note : changes)
            notes->push_back(plainMessage(fromStd(note)));
    }
    return pushChange(changed, GeometryChange | RoomsChange | EndpointsChange, tr("Repair plan"));
}

Document::~Document() = default;

void Document::setFileName(const QString& fileName) {
    if (fileName_ == fileName)
        return;
    fileName_ = fileName;
    emit fileNameChanged(fileName_);
}

QString Document::displayName() const {
    if (!fileName_.isEmpty())
        return QFileInfo(fileName_).fileName();
    if (!project_.plan.name.empty())
        return fromStd(project_.plan.name);
    return tr("Untitled");
}

bool Document::isModified() const {
    return !undoStack_->isClean();
}

void Document::markSaved() {
    undoStack_->setClean();
}

void Document::markModified() {
    undoStack_->resetClean();
    emit modifiedChanged(true);
}

int Document::polygonCount(PolygonRole role) const {
    switch (role) {
    case PolygonRole::Boundary:
        return project_.plan.boundary.empty() ? 0 : 1;
    case PolygonRole::Obstacle:
        return static_cast<int>(project_.plan.obstacles.size());
    case PolygonRole::Room:
        return static_cast<int>(project_.plan.rooms.size());
    }
    return 0;
}

const Ring& Document::ring(PolygonRef ref) const {
    switch (ref.role) {
    case PolygonRole::Obstacle:
        return project_.plan.obstacles.at(ref.index);
    case PolygonRole::Room:
        return project_.plan.rooms.at(ref.index).outline;
    case PolygonRole::Boundary:
        break;
    }
    return project_.plan.boundary;
}

QStringList Document::roomNames() const {
    QStringList names;
    for (const Room& room : project_.plan.rooms)
        names << fromStd(room.name);
    if (names.isEmpty())
        names << QString::fromLatin1(kFloorRoom);
    return names;
}

bool Document::isRoomSelected(const QString& name) const {
    const auto& selected = project_.selectedRooms;
    return selected.empty() ||
           std::find(selected.begin(), selected.end(), name.toStdString()) != selected.end();
}

std::optional<QString> Document::roomAt(Vec2 point) const {
    const auto& rooms = project_.plan.rooms;
    for (auto it = rooms.rbegin(); it != rooms.rend(); ++it)
        if (pointInRing(it->outline, point))
            return fromStd(it->name);
    if (rooms.empty() && !project_.plan.boundary.empty() &&
        pointInRing(project_.plan.boundary, point))
        return QString::fromLatin1(kFloorRoom);
    return std::nullopt;
}

QString Document::validationMessage(const Plan& plan) const {
    if (plan.boundary.empty()) {
        if (plan.obstacles.empty() && plan.rooms.empty())
            return {};
        return tr("Draw the boundary first: obstacles and rooms must lie inside it.");
    }
    try {
        validatePlan(normalizedPlan(plan), project_.robot);
    } catch (const InputError& e) {
        return plainMessage(fromStd(e.what())); // in the editor's words and language
    }
    return {};
}

bool Document::reject(const QString& message) {
    emit editRejected(message);
    return false;
}

bool Document::pushChange(const Project& changed, unsigned changes, const QString& text,
                          int mergeId) {
    if (needsRepair() && !validationMessage(changed.plan).isEmpty())
        return reject(tr("This plan has problems (see the Problems panel): repair it first "
                         "with Plan > Repair Plan, or undo back to a valid plan."));
    if (changes & (GeometryChange | RoomsChange)) {
        const QString problem = validationMessage(changed.plan);
        if (!problem.isEmpty())
            return reject(problem);
    }
    undoStack_->push(new ProjectChangeCommand(this, changed, changes, text, mergeId));
    return true;
}

bool Document::replaceProject(const Project& project, const QString& commandText) {
    return pushChange(project,
                      GeometryChange | RoomsChange | RobotChange | SweepChange | EndpointsChange |
                          SolverChange,
                      commandText);
}

void Document::applyProject(const Project& project, unsigned changes) {
    project_ = project;
    if (changes & (GeometryChange | RoomsChange))
        updateProblems();
    if (changes & GeometryChange)
        emit geometryChanged();
    if (changes & RoomsChange)
        emit roomsChanged();
    if (changes & RobotChange)
        emit robotChanged();
    if (changes & SweepChange)
        emit sweepChanged();
    if (changes & EndpointsChange)
        emit endpointsChanged();
    if (changes & SolverChange)
        emit solverChanged();
}

QString Document::uniqueRoomName() const {
    const QStringList names = roomNames();
    for (int n = static_cast<int>(project_.plan.rooms.size()) + 1;; ++n) {
        const QString name = tr("Room %1").arg(n);
        if (!names.contains(name))
            return name;
    }
}

bool Document::addPolygon(PolygonRole role, const Ring& ring) {
    Project changed = project_;
    QString text;
    unsigned changes = GeometryChange;
    switch (role) {
    case PolygonRole::Boundary:
        text = project_.plan.boundary.empty() ? tr("Add boundary") : tr("Replace boundary");
        changed.plan.boundary = ring;
        break;
    case PolygonRole::Obstacle:
        text = tr("Add obstacle");
        changed.plan.obstacles.push_back(ring);
        break;
    case PolygonRole::Room: {
        const QString name = uniqueRoomName();
        text = tr("Add room %1").arg(name);
        changed.plan.rooms.push_back({name.toStdString(), ring});
        // A new room joins an explicit selection so that it is planned like the others.
        if (!changed.selectedRooms.empty())
            changed.selectedRooms.push_back(name.toStdString());
        changes |= RoomsChange;
        break;
    }
    }
    return pushChange(changed, changes, text);
}

bool Document::isValid(PolygonRef ref, int vertex) const {
    if (ref.index < 0 || ref.index >= polygonCount(ref.role))
        return false;
    return vertex < 0 || vertex < static_cast<int>(ring(ref).size());
}

bool Document::replaceRing(PolygonRef ref, const Ring& ring, const QString& commandText,
                           int mergeId) {
    if (!isValid(ref))
        return reject(tr("There is no such polygon."));
    Project changed = project_;
    switch (ref.role) {
    case PolygonRole::Boundary:
        changed.plan.boundary = ring;
        break;
    case PolygonRole::Obstacle:
        changed.plan.obstacles.at(ref.index) = ring;
        break;
    case PolygonRole::Room:
        changed.plan.rooms.at(ref.index).outline = ring;
        break;
    }
    return pushChange(changed, GeometryChange, commandText, mergeId);
}

bool Document::moveVertex(PolygonRef ref, int vertex, Vec2 position) {
    if (!isValid(ref, vertex) || vertex < 0)
        return reject(tr("There is no such vertex."));
    Ring moved = ring(ref);
    moved.at(vertex) = position;
    return replaceRing(ref, moved, tr("Move vertex"));
}

bool Document::insertVertex(PolygonRef ref, int beforeVertex, Vec2 position) {
    if (!isValid(ref))
        return reject(tr("There is no such polygon."));
    Ring grown = ring(ref);
    grown.insert(grown.begin() + std::clamp(beforeVertex, 0, static_cast<int>(grown.size())),
                 position);
    return replaceRing(ref, grown, tr("Insert vertex"));
}

bool Document::deleteVertex(PolygonRef ref, int vertex) {
    if (!isValid(ref, vertex) || vertex < 0)
        return reject(tr("There is no such vertex."));
    Ring shrunk = ring(ref);
    if (shrunk.size() <= 3)
        return reject(tr("A polygon needs at least three vertices; delete the polygon instead."));
    shrunk.erase(shrunk.begin() + vertex);
    return replaceRing(ref, shrunk, tr("Delete vertex"));
}

bool Document::deletePolygon(PolygonRef ref) {
    if (!isValid(ref))
        return reject(tr("There is no such polygon."));
    Project changed = project_;
    unsigned changes = GeometryChange;
    QString text;
    switch (ref.role) {
    case PolygonRole::Boundary:
        if (!changed.plan.obstacles.empty() || !changed.plan.rooms.empty())
            return reject(tr("Delete the obstacles and rooms before the boundary."));
        changed.plan.boundary.clear();
        text = tr("Delete boundary");
        break;
    case PolygonRole::Obstacle:
        changed.plan.obstacles.erase(changed.plan.obstacles.begin() + ref.index);
        text = tr("Delete obstacle");
        break;
    case PolygonRole::Room: {
        const std::string name = changed.plan.rooms.at(ref.index).name;
        changed.plan.rooms.erase(changed.plan.rooms.begin() + ref.index);
        auto& selected = changed.selectedRooms;
        selected.erase(std::remove(selected.begin(), selected.end(), name), selected.end());
        changed.sweep.roomAngles.erase(name);
        text = tr("Delete room %1").arg(fromStd(name));
        changes |= RoomsChange | SweepChange;
        break;
    }
    }
    return pushChange(changed, changes, text);
}

bool Document::renameRoom(int index, const QString& name) {
    const QString trimmed = name.trimmed();
    if (index < 0 || index >= polygonCount(PolygonRole::Room))
        return reject(tr("There is no room %1.").arg(index + 1));
    const QString old = fromStd(project_.plan.rooms[index].name);
    if (trimmed == old)
        return true;
    if (trimmed.isEmpty())
        return reject(tr("A room needs a name."));
    if (roomNames().contains(trimmed))
        return reject(tr("There is already a room named \"%1\".").arg(trimmed));
    Project changed = project_;
    changed.plan.rooms[index].name = trimmed.toStdString();
    auto it = findName(changed.selectedRooms, old.toStdString());
    if (it != changed.selectedRooms.end())
        *it = trimmed.toStdString();
    // A fixed angle stays with the room under its new name.
    auto& angles = changed.sweep.roomAngles;
    if (auto fixed = angles.find(old.toStdString()); fixed != angles.end()) {
        angles[trimmed.toStdString()] = fixed->second;
        angles.erase(old.toStdString());
    }
    return pushChange(changed, RoomsChange | SweepChange,
                      tr("Rename room %1 to %2").arg(old, trimmed));
}

bool Document::setRobot(const RobotProfile& robot) {
    try {
        robot.validate();
    } catch (const InputError& e) {
        return reject(plainMessage(fromStd(e.what())));
    }
    // Steps of one spin box merge into one command; a change of another field does not.
    const RobotProfile& old = project_.robot;
    const double RobotProfile::*fields[] = {
        &RobotProfile::robotDiameter, &RobotProfile::cleaningDiameter, &RobotProfile::coverageWidth,
        &RobotProfile::speed, &RobotProfile::turnTime};
    int mergeId = -1;
    for (int i = 0; i < 5; ++i)
        if (old.*fields[i] != robot.*fields[i])
            mergeId = mergeId == -1 ? kRobotMergeId + i : -2;
    Project changed = project_;
    changed.robot = robot;
    return pushChange(changed, RobotChange, tr("Change robot profile"), std::max(mergeId, -1));
}

bool Document::setSweep(const SweepOptions& sweep) {
    if (!std::isfinite(sweep.angleDeg))
        return reject(tr("The sweep angle must be a finite number of degrees."));
    Project changed = project_;
    changed.sweep = sweep;
    return pushChange(changed, SweepChange, tr("Change sweep angle"), kSweepMergeId);
}

bool Document::setSolver(const QString& solver) {
    Project changed = project_;
    changed.solver = solver.toStdString();
    return pushChange(changed, SolverChange, tr("Choose solver %1").arg(solver));
}

bool Document::setStart(std::optional<Vec2> start) {
    Project changed = project_;
    changed.hasStart = start.has_value();
    changed.start = start.value_or(Vec2{});
    return pushChange(changed, EndpointsChange, start ? tr("Place start") : tr("Remove start"));
}

bool Document::setEnd(std::optional<Vec2> end) {
    Project changed = project_;
    changed.hasEnd = end.has_value();
    changed.end = end.value_or(Vec2{});
    return pushChange(changed, EndpointsChange, end ? tr("Place end") : tr("Remove end"));
}

bool Document::toggleRoomSelection(const QString& name) {
    const QStringList all = roomNames();
    if (!all.contains(name))
        return reject(tr("There is no room named \"%1\".").arg(name));
    std::vector<std::string> selected;
    for (const QString& room : all) {
        const bool on = isRoomSelected(room);
        if (room == name ? !on : on)
            selected.push_back(room.toStdString());
    }
    if (selected.empty())
        return reject(tr("At least one room must stay selected for planning."));
    if (selected.size() == static_cast<size_t>(all.size()))
        selected.clear(); // the project's way of saying "every room"
    Project changed = project_;
    changed.selectedRooms = selected;
    const QString text =
        isRoomSelected(name) ? tr("Deselect room %1").arg(name) : tr("Select room %1").arg(name);
    return pushChange(changed, RoomsChange, text);
}

} // namespace fc::ui

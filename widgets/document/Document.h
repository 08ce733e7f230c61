// The edited project: owns the planner's Project value and the undo stack. Every change
// goes through a ProjectChangeCommand so that it can be undone; the typed signals tell the
// scene, the docks and the planning controller which part changed.
#pragma once

#include "formats/PlanIO.h"
#include "model/Validation.h"

#include <QObject>
#include <QString>
#include <QStringList>
#include <optional>

class QUndoStack;

namespace fc::ui {

enum class PolygonRole { Boundary, Obstacle, Room };

// Addresses one ring of the plan: the boundary, obstacle `index` or room `index`.
struct PolygonRef {
    PolygonRole role = PolygonRole::Boundary;
    int index = 0;
    bool operator==(const PolygonRef& o) const { return role == o.role && index == o.index; }
    bool operator!=(const PolygonRef& o) const { return !(*this == o); }
};

// Which parts of the project an edit touched (decides the signals emitted).
enum Change : unsigned {
    GeometryChange = 1u << 0,  // boundary, obstacles, room outlines
    RoomsChange = 1u << 1,     // room list, names, planning selection
    RobotChange = 1u << 2,     // robot profile
    SweepChange = 1u << 3,     // sweep angle / auto
    EndpointsChange = 1u << 4, // start and end points
    SolverChange = 1u << 5,
};

class Document : public QObject {
    Q_OBJECT
public:
    explicit Document(Project project = {}, QObject* parent = nullptr);
    ~Document() override;

    const Project& project() const { return project_; }
    const Plan& plan() const { return project_.plan; }
    QUndoStack* undoStack() const { return undoStack_; }

    // The .fcproj file the document is saved to; empty for new or imported documents.
    QString fileName() const { return fileName_; }
    void setFileName(const QString& fileName);
    QString displayName() const;
    bool isModified() const;
    void markSaved();
    // Modified until the next save, whatever is undone (a recovered document).
    void markModified();

    int polygonCount(PolygonRole role) const;
    // Whether the polygon (and, when vertex >= 0, its vertex) exists.
    bool isValid(PolygonRef ref, int vertex = -1) const;
    const Ring& ring(PolygonRef ref) const;
    // The names the planner uses for selection: the rooms, or "Floor" when there are none.
    QStringList roomNames() const;
    bool isRoomSelected(const QString& name) const;
    // The room under a point (the last drawn wins), or "Floor" inside a plan without rooms.
    std::optional<QString> roomAt(Vec2 point) const;

    // A plan the planner refuses (opened or imported with self-intersections, obstacles
    // across the wall...) is held read-only: its problems are listed and shown, and only an
    // edit that makes it valid is accepted: repair() or a fix that removes every problem.
    bool needsRepair() const { return !problems_.empty(); }
    const std::vector<PlanProblem>& problems() const { return problems_; }
    // Makes the plan valid (fc::repairPlan, GEOS) as one undoable edit; *notes says what
    // changed. False (and editRejected) when the repair cannot make it valid.
    bool repair(QStringList* notes = nullptr);

    // The planner's validation of a candidate plan; empty when it is acceptable. A plan
    // without a boundary is accepted only while it is still empty (a new drawing).
    QString validationMessage(const Plan& plan) const;

    // Edits. Each validates, pushes one undoable command and returns true; on invalid input
    // it changes nothing, emits editRejected(message) and returns false.
    bool addPolygon(PolygonRole role, const Ring& ring);
    bool replaceRing(PolygonRef ref, const Ring& ring, const QString& commandText,
                     int mergeId = -1);
    bool moveVertex(PolygonRef ref, int vertex, Vec2 position);
    bool insertVertex(PolygonRef ref, int beforeVertex, Vec2 position);
    bool deleteVertex(PolygonRef ref, int vertex);
    bool deletePolygon(PolygonRef ref);
    bool renameRoom(int index, const QString& name);
    // Rooms found in a map, reshaped (DocumentRooms.cpp): two rooms that share a border
    // become one (the first keeps its name, its place and its fixed angle), and a room is
    // cut in two along the line through `from` and `to` (the new part named "Room n").
    bool mergeRooms(int first, int second);
    bool splitRoom(int index, Vec2 from, Vec2 to);
    bool setRobot(const RobotProfile& robot);
    bool setSweep(const SweepOptions& sweep);
    bool setSolver(const QString& solver);
    bool setStart(std::optional<Vec2> start);
    bool setEnd(std::optional<Vec2> end);
    bool toggleRoomSelection(const QString& name);
    // Replaces the whole project (File > Import into this document) as one undoable edit.
    bool replaceProject(const Project& project, const QString& commandText);

    // Used by ProjectChangeCommand only: replaces the project and emits the signals.
    void applyProject(const Project& project, unsigned changes);

signals:
    void geometryChanged();
    void roomsChanged();
    void robotChanged();
    void sweepChanged();
    void endpointsChanged();
    void solverChanged();
    void modifiedChanged(bool modified);
    void fileNameChanged(const QString& fileName);
    void editRejected(const QString& message);

private:
    bool pushChange(const Project& changed, unsigned changes, const QString& text,
                    int mergeId = -1);
    bool reject(const QString& message);
    QString uniqueRoomName() const;

    void updateProblems();

    Project project_;
    std::vector<PlanProblem> problems_;
    QUndoStack* undoStack_;
    QString fileName_;
};

} // namespace fc::ui

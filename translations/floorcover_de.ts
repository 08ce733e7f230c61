<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>PlannerMessages</name>
    <message>
        <source>The exact solver could not prove the best order of %1 cells within its budget (%2). Choose the heuristic solver in the Planning panel.</source>
        <translation>Der exakte Löser konnte die beste Reihenfolge von %1 Zellen in seinem Budget (%2) nicht beweisen. Wählen Sie im Bereich Planung den heuristischen Löser.</translation>
    </message>
    <message>
        <source>These rooms have %1 cells, and the exact solver orders at most %2. Choose the heuristic solver in the Planning panel.</source>
        <translation>Diese Räume haben %1 Zellen, der exakte Löser ordnet aber höchstens %2. Wählen Sie im Bereich Planung den heuristischen Löser.</translation>
    </message>
    <message>
        <source>Obstacle %1 crosses the outer wall near %2.</source>
        <translation>Hindernis %1 kreuzt die Außenwand bei %2.</translation>
    </message>
    <message>
        <source>Obstacle %1 touches the outer wall at %2; obstacles must lie inside the walls.</source>
        <translation>Hindernis %1 berührt die Außenwand bei %2; Hindernisse müssen innerhalb der Wände liegen.</translation>
    </message>
    <message>
        <source>Obstacles %1 and %2 overlap near %3.</source>
        <translation>Die Hindernisse %1 und %2 überlappen sich bei %3.</translation>
    </message>
    <message>
        <source>Obstacles %1 and %2 touch at %3; draw them as one obstacle.</source>
        <translation>Die Hindernisse %1 und %2 berühren sich bei %3; zeichnen Sie sie als ein Hindernis.</translation>
    </message>
    <message>
        <source>Obstacle %1 lies outside the walls, near %2.</source>
        <translation>Hindernis %1 liegt außerhalb der Wände, bei %2.</translation>
    </message>
    <message>
        <source>Obstacle %1 lies inside obstacle %2.</source>
        <translation>Hindernis %1 liegt in Hindernis %2.</translation>
    </message>
    <message>
        <source>%1 crosses itself near %2.</source>
        <translation>%1 kreuzt sich selbst bei %2.</translation>
    </message>
    <message>
        <source>%1 touches itself at %2.</source>
        <translation>%1 berührt sich selbst bei %2.</translation>
    </message>
    <message>
        <source>%1 folds back on itself (a spike) at %2.</source>
        <translation>%1 knickt bei %2 auf sich selbst zurück (eine Spitze).</translation>
    </message>
    <message>
        <source>Rooms “%1” and “%2” overlap by %3 m² near %4.</source>
        <translation>Die Räume „%1“ und „%2“ überlappen sich um %3 m² bei %4.</translation>
    </message>
    <message>
        <source>Rooms “%1” and “%2” overlap by %3 m².</source>
        <translation>Die Räume „%1“ und „%2“ überlappen sich um %3 m².</translation>
    </message>
    <message>
        <source>Room “%1” lies outside the walls.</source>
        <translation>Raum „%1“ liegt außerhalb der Wände.</translation>
    </message>
    <message>
        <source>Room “%1” lies inside obstacle %2.</source>
        <translation>Raum „%1“ liegt in Hindernis %2.</translation>
    </message>
    <message>
        <source>Two rooms are named “%1”: rename one.</source>
        <translation>Zwei Räume heißen „%1“: Benennen Sie einen davon um.</translation>
    </message>
    <message>
        <source>%1 cells (%2 m²) cannot be reached from the start and are left out.</source>
        <translation>%1 Zellen (%2 m²) sind vom Start aus nicht erreichbar und werden ausgelassen.</translation>
    </message>
    <message>
        <source>Room %1 cannot be reached from the start and is left out.</source>
        <translation>Raum %1 ist vom Start aus nicht erreichbar und wird ausgelassen.</translation>
    </message>
    <message>
        <source>%1 m² (%2 % of the selected floor) the robot could clean but the path misses.</source>
        <translation>%1 m² (%2 % der ausgewählten Fläche) könnte der Roboter reinigen, aber der Pfad lässt sie aus.</translation>
    </message>
    <message>
        <source>%1 m² (%2 % of the selected floor) the robot cannot reach (gaps narrower than the robot, corners beyond its head).</source>
        <translation>%1 m² (%2 % der ausgewählten Fläche) kann der Roboter nicht erreichen (Durchgänge schmaler als der Roboter, Ecken außer Reichweite seines Reinigungskopfs).</translation>
    </message>
    <message>
        <source>No selected room can be reached from the start: move the start (Place Start) or pick other rooms.</source>
        <translation>Kein ausgewählter Raum ist vom Start aus erreichbar: Verschieben Sie den Start (Start setzen) oder wählen Sie andere Räume.</translation>
    </message>
    <message>
        <source>The end cannot be reached from the start: move one of them.</source>
        <translation>Das Ziel ist vom Start aus nicht erreichbar: Verschieben Sie eines von beiden.</translation>
    </message>
    <message>
        <source>The selected rooms have no floor the robot can clean: pick other rooms or a smaller robot.</source>
        <translation>Die ausgewählten Räume haben keinen Boden, den der Roboter reinigen kann: Wählen Sie andere Räume oder einen kleineren Roboter.</translation>
    </message>
    <message>
        <source>The robot diameter L (%1 m) is larger than the coverage width W (%2 m): L ≤ W ≤ D.</source>
        <translation>Der Roboterdurchmesser L (%1 m) ist größer als die Bahnbreite W (%2 m): L ≤ W ≤ D.</translation>
    </message>
    <message>
        <source>The coverage width W (%1 m) is larger than the cleaning diameter D (%2 m): L ≤ W ≤ D.</source>
        <translation>Die Bahnbreite W (%1 m) ist größer als der Reinigungsdurchmesser D (%2 m): L ≤ W ≤ D.</translation>
    </message>
    <message>
        <source>The outer wall</source>
        <translation>Die Außenwand</translation>
    </message>
    <message>
        <source>Obstacle %1</source>
        <translation>Hindernis %1</translation>
    </message>
    <message>
        <source>Room “%1”</source>
        <translation>Raum „%1“</translation>
    </message>
    <message>
        <source>Obstacles %1 and %2 are the same: delete one of them.</source>
        <translation>Die Hindernisse %1 und %2 sind gleich: Löschen Sie eines davon.</translation>
    </message>
    <message>
        <source>Room “%1” covers only obstacles: there is no floor in it to clean.</source>
        <translation>Raum „%1“ bedeckt nur Hindernisse: Darin gibt es keine Fläche zu reinigen.</translation>
    </message>
    <message>
        <source>Room %1 has no name: give it one.</source>
        <translation>Raum %1 hat keinen Namen: Geben Sie ihm einen.</translation>
    </message>
    <message>
        <source>The free floor (%1 m²) is smaller than the robot (%2 m², L = %3 m).</source>
        <translation>Die freie Fläche (%1 m²) ist kleiner als der Roboter (%2 m², L = %3 m).</translation>
    </message>
    <message>
        <source>%1 (feature %2)</source>
        <translation>%1 (Objekt %2)</translation>
    </message>
    <message>
        <source>%1 (hole %2 in the outer wall)</source>
        <translation>%1 (Loch %2 in der Außenwand)</translation>
    </message>
    <message>
        <source>%1 (outer wall)</source>
        <translation>%1 (Außenwand)</translation>
    </message>
    <message>
        <source>%1 (obstacle)</source>
        <translation>%1 (Hindernis)</translation>
    </message>
    <message>
        <source>%1 (room)</source>
        <translation>%1 (Raum)</translation>
    </message>
    <message>
        <source>A room</source>
        <translation>Ein Raum</translation>
    </message>
    <message>
        <source>An unnamed room</source>
        <translation>Ein unbenannter Raum</translation>
    </message>
    <message>
        <source>Room %1</source>
        <translation>Raum %1</translation>
    </message>
    <message>
        <source>Feature %1</source>
        <translation>Objekt %1</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>The free floor (%1 m²) is smaller than one coverage square W² (%2 m²): make the coverage width W smaller in the Planning panel.</source>
        <translation>Die freie Fläche (%1 m²) ist kleiner als ein Quadrat der Bahnbreite W² (%2 m²): Verkleinern Sie die Bahnbreite W im Bereich Planung.</translation>
    </message>
    <message>
        <source>%1: vertex %2 has a coordinate that is not a finite number.</source>
        <translation>%1: Eckpunkt %2 hat eine Koordinate, die keine endliche Zahl ist.</translation>
    </message>
    <message>
        <source>%1 has two vertices on top of each other at %3 (vertex %2): delete one of them (Edit Vertices, right-click).</source>
        <translation>%1 hat bei %3 zwei Eckpunkte übereinander (Eckpunkt %2): Löschen Sie einen davon (Eckpunkte bearbeiten, Rechtsklick).</translation>
    </message>
    <message>
        <source>%1 has no area: all its vertices lie on one line.</source>
        <translation>%1 hat keine Fläche: Alle Eckpunkte liegen auf einer Linie.</translation>
    </message>
    <message>
        <source>The robot diameter L must be a positive number, not %1: change it in the Planning panel.</source>
        <translation>Der Roboterdurchmesser L muss eine positive Zahl sein, nicht %1: Ändern Sie ihn im Bereich Planung.</translation>
    </message>
    <message>
        <source>The coverage width W must be a positive number, not %1: change it in the Planning panel.</source>
        <translation>Die Bahnbreite W muss eine positive Zahl sein, nicht %1: Ändern Sie sie im Bereich Planung.</translation>
    </message>
    <message>
        <source>The cleaning diameter D must be a positive number, not %1: change it in the Planning panel.</source>
        <translation>Der Reinigungsdurchmesser D muss eine positive Zahl sein, nicht %1: Ändern Sie ihn im Bereich Planung.</translation>
    </message>
    <message>
        <source>The speed must be a positive number, not %1: change it in the Planning panel.</source>
        <translation>Die Geschwindigkeit muss eine positive Zahl sein, nicht %1: Ändern Sie sie im Bereich Planung.</translation>
    </message>
    <message>
        <source>The robot&apos;s turn time must be zero or positive, not %1.</source>
        <translation>Die Wendezeit des Roboters muss null oder positiv sein, nicht %1.</translation>
    </message>
    <message>
        <source>A coverage width W of %1 m is not a plausible robot size: change it in the Planning panel.</source>
        <translation>Eine Bahnbreite W von %1 m ist keine plausible Robotergröße: Ändern Sie sie im Bereich Planung.</translation>
    </message>
    <message>
        <source>one of the rooms has fewer than three corners</source>
        <translation>einer der Räume hat weniger als drei Ecken</translation>
    </message>
    <message>
        <source>they do not share a border; merge rooms that meet along a wall or a doorway</source>
        <translation>sie haben keine gemeinsame Grenze; führen Sie Räume zusammen, die an einer Wand oder einem Durchgang aneinanderstoßen</translation>
    </message>
    <message>
        <source>the merged room would fall apart into several pieces</source>
        <translation>der zusammengeführte Raum würde in mehrere Teile zerfallen</translation>
    </message>
    <message>
        <source>the merged room would enclose a hole; merge the room inside it as well</source>
        <translation>der zusammengeführte Raum würde ein Loch umschließen; führen Sie auch den Raum darin mit zusammen</translation>
    </message>
    <message>
        <source>the room has fewer than three corners</source>
        <translation>der Raum hat weniger als drei Ecken</translation>
    </message>
    <message>
        <source>drag the cut as a line across the room (Split Room)</source>
        <translation>ziehen Sie den Schnitt als Linie quer durch den Raum (Raum teilen)</translation>
    </message>
    <message>
        <source>the cut does not cross the room; drag it from one wall of the room to another</source>
        <translation>der Schnitt kreuzt den Raum nicht; ziehen Sie ihn von einer Wand des Raums zu einer anderen</translation>
    </message>
    <message>
        <source>the cut crosses the room more than once; drag it where one straight line divides the room in two</source>
        <translation>der Schnitt kreuzt den Raum mehr als einmal; ziehen Sie ihn dort, wo eine gerade Linie den Raum in zwei Teile teilt</translation>
    </message>
    <message>
        <source>the cut would cut off only a sliver of the room; drag it across the middle of the room</source>
        <translation>der Schnitt würde nur einen schmalen Streifen des Raums abtrennen; ziehen Sie ihn durch die Mitte des Raums</translation>
    </message>
    <message>
        <source>The sweep angle must be a finite number of degrees: set it in the Planning panel.</source>
        <translation>Der Bahnwinkel muss eine endliche Gradzahl sein: Stellen Sie ihn im Bereich Planung ein.</translation>
    </message>
    <message>
        <source>There is no room “%1” in this plan (its rooms: %2): check the rooms to plan in the Planning panel.</source>
        <translation>In diesem Plan gibt es keinen Raum „%1“ (seine Räume: %2): Prüfen Sie die zu planenden Räume im Bereich Planung.</translation>
    </message>
    <message>
        <source>There is no solver “%1” (available: %2): choose one in the Planning panel.</source>
        <translation>Es gibt keinen Löser „%1“ (verfügbar: %2): Wählen Sie einen im Bereich Planung.</translation>
    </message>
    <message>
        <source>The robot finds no way into room “%1” from the room before it: widen the passage, or sweep the floor at one angle (Sweep in the Planning panel).</source>
        <translation>Der Roboter findet aus dem vorigen Raum keinen Weg in den Raum „%1“: Verbreitern Sie den Durchgang oder fahren Sie die Fläche in einem Winkel ab (Bahnen im Bereich Planung).</translation>
    </message>
    <message>
        <source>Cancelled.</source>
        <translation>Abgebrochen.</translation>
    </message>
    <message>
        <source>The %1 solver was cancelled.</source>
        <translation>Der Löser %1 wurde abgebrochen.</translation>
    </message>
    <message>
        <source>The %1 solver cannot reach %2 cells from the start: move the start (Place Start) or pick other rooms.</source>
        <translation>Der Löser %1 kann %2 Zellen vom Start aus nicht erreichen: Verschieben Sie den Start (Start setzen) oder wählen Sie andere Räume.</translation>
    </message>
    <message>
        <source>The %1 solver cannot reach the end from the start: move one of them.</source>
        <translation>Der Löser %1 kann das Ziel vom Start aus nicht erreichen: Verschieben Sie eines von beiden.</translation>
    </message>
    <message>
        <source>The %1 solver stopped on an internal error (%2): please report it, and choose another solver in the Planning panel meanwhile.</source>
        <translation>Der Löser %1 hat wegen eines internen Fehlers angehalten (%2): Bitte melden Sie ihn und wählen Sie bis dahin im Bereich Planung einen anderen Löser.</translation>
    </message>
    <message>
        <source>The dqn model is inconsistent (its network does not fit its kind of state): train a new model in the Training panel.</source>
        <translation>Das dqn-Modell ist widersprüchlich (sein Netz passt nicht zu seiner Art von Zustand): Trainieren Sie im Bereich Training ein neues Modell.</translation>
    </message>
    <message>
        <source>The dqn model was trained on a plan of another size: train a model for this plan in the Training panel.</source>
        <translation>Das dqn-Modell wurde auf einem Plan anderer Größe trainiert: Trainieren Sie im Bereich Training ein Modell für diesen Plan.</translation>
    </message>
    <message>
        <source>The dqn solver cannot plan this query (%1): choose another solver in the Planning panel.</source>
        <translation>Der Löser dqn kann diese Anfrage nicht planen (%1): Wählen Sie im Bereich Planung einen anderen Löser.</translation>
    </message>
    <message>
        <source>The dqn solver finds no way to the rooms still to clean: choose another solver in the Planning panel.</source>
        <translation>Der Löser dqn findet keinen Weg zu den noch zu reinigenden Räumen: Wählen Sie im Bereich Planung einen anderen Löser.</translation>
    </message>
    <message>
        <source>The dqn model ran out of steps before it covered the rooms: train it longer in the Training panel, or choose another solver.</source>
        <translation>Dem dqn-Modell gingen die Schritte aus, bevor es die Räume abgedeckt hatte: Trainieren Sie es im Bereich Training länger oder wählen Sie einen anderen Löser.</translation>
    </message>
    <message>
        <source>The path of the dqn solver does not cover the rooms (an internal error): choose another solver in the Planning panel.</source>
        <translation>Der Pfad des Lösers dqn deckt die Räume nicht ab (ein interner Fehler): Wählen Sie im Bereich Planung einen anderen Löser.</translation>
    </message>
    <message>
        <source>The plan has no floor the robot can reach: there is nothing to train on.</source>
        <translation>Der Plan hat keine Fläche, die der Roboter erreichen kann: Es gibt nichts zu trainieren.</translation>
    </message>
    <message>
        <source>The model file is incomplete: load another model or train a new one in the Training panel.</source>
        <translation>Die Modelldatei ist unvollständig: Laden Sie ein anderes Modell oder trainieren Sie im Bereich Training ein neues.</translation>
    </message>
    <message>
        <source>The model file is damaged: load another model or train a new one in the Training panel.</source>
        <translation>Die Modelldatei ist beschädigt: Laden Sie ein anderes Modell oder trainieren Sie im Bereich Training ein neues.</translation>
    </message>
    <message>
        <source>This is not a FloorCover dqn model file (.fcdqn).</source>
        <translation>Dies ist keine dqn-Modelldatei von FloorCover (.fcdqn).</translation>
    </message>
    <message>
        <source>The model file has format version %1, and this FloorCover reads versions up to %2: update FloorCover or train a new model.</source>
        <translation>Die Modelldatei hat die Formatversion %1, dieses FloorCover liest Versionen bis %2: Aktualisieren Sie FloorCover oder trainieren Sie ein neues Modell.</translation>
    </message>
    <message>
        <source>The model file cannot be opened: check that it exists and can be read.</source>
        <translation>Die Modelldatei lässt sich nicht öffnen: Prüfen Sie, ob sie existiert und lesbar ist.</translation>
    </message>
    <message>
        <source>This model was trained for another floor plan or robot (%1 corners in %2 cells, sweep angle %3°, coverage width %4 m; this plan has %5 corners in %6 cells): train a model for this plan in the Training panel.</source>
        <translation>Dieses Modell wurde für einen anderen Grundriss oder Roboter trainiert (%1 Ecken in %2 Zellen, Bahnwinkel %3°, Bahnbreite %4 m; dieser Plan hat %5 Ecken in %6 Zellen): Trainieren Sie im Bereich Training ein Modell für diesen Plan.</translation>
    </message>
    <message>
        <source>There is no such file.</source>
        <translation>Diese Datei gibt es nicht.</translation>
    </message>
    <message>
        <source>This is a folder, not a file.</source>
        <translation>Dies ist ein Ordner, keine Datei.</translation>
    </message>
    <message>
        <source>The file cannot be read (%1).</source>
        <translation>Die Datei kann nicht gelesen werden (%1).</translation>
    </message>
    <message>
        <source>The file cannot be written (%1): choose another folder, or check that this one can be written to.</source>
        <translation>Die Datei kann nicht geschrieben werden (%1): Wählen Sie einen anderen Ordner oder prüfen Sie, ob in diesen geschrieben werden darf.</translation>
    </message>
    <message>
        <source>The file name has no extension: FloorCover opens .fcproj projects and .geojson or .json plans; other formats come in with File &gt; Import…</source>
        <translation>Der Dateiname hat keine Endung: FloorCover öffnet .fcproj-Projekte und .geojson- oder .json-Pläne; andere Formate kommen über Datei &gt; Importieren… herein.</translation>
    </message>
    <message>
        <source>FloorCover opens .fcproj projects and .geojson or .json plans, not “%1” files; other formats come in with File &gt; Import…</source>
        <translation>FloorCover öffnet .fcproj-Projekte und .geojson- oder .json-Pläne, keine „%1“-Dateien; andere Formate kommen über Datei &gt; Importieren… herein.</translation>
    </message>
    <message>
        <source>The file is larger than %1, more than FloorCover imports.</source>
        <translation>Die Datei ist größer als %1, mehr als FloorCover importiert.</translation>
    </message>
    <message>
        <source>The file is empty.</source>
        <translation>Die Datei ist leer.</translation>
    </message>
    <message>
        <source>The file ends too early (line %1, column %2): it may have been cut off while it was written.</source>
        <translation>Die Datei endet zu früh (Zeile %1, Spalte %2): Sie wurde vielleicht beim Schreiben abgeschnitten.</translation>
    </message>
    <message>
        <source>The file ends too early: it may have been cut off while it was written.</source>
        <translation>Die Datei endet zu früh: Sie wurde vielleicht beim Schreiben abgeschnitten.</translation>
    </message>
    <message>
        <source>The file is not valid JSON at line %1, column %2 (%3).</source>
        <translation>Die Datei ist in Zeile %1, Spalte %2 kein gültiges JSON (%3).</translation>
    </message>
    <message>
        <source>The file is not valid JSON (%1).</source>
        <translation>Die Datei ist kein gültiges JSON (%1).</translation>
    </message>
    <message>
        <source>The number %1 at line %2, column %3 is too large for a coordinate.</source>
        <translation>Die Zahl %1 in Zeile %2, Spalte %3 ist zu groß für eine Koordinate.</translation>
    </message>
    <message>
        <source>The number %1 is too large for a coordinate.</source>
        <translation>Die Zahl %1 ist zu groß für eine Koordinate.</translation>
    </message>
    <message>
        <source>A number in the file is out of range (%1).</source>
        <translation>Eine Zahl in der Datei liegt außerhalb des gültigen Bereichs (%1).</translation>
    </message>
    <message>
        <source>%1: the coordinates must be a list of [x, y] positions, not %2.</source>
        <translation>%1: Die Koordinaten müssen eine Liste von [x, y]-Positionen sein, nicht %2.</translation>
    </message>
    <message>
        <source>%1: vertex %2 is not an [x, y] position but %3.</source>
        <translation>%1: Eckpunkt %2 ist keine [x, y]-Position, sondern %3.</translation>
    </message>
    <message>
        <source>%1: vertex %2 has a coordinate that is not a number (%3).</source>
        <translation>%1: Eckpunkt %2 hat eine Koordinate, die keine Zahl ist (%3).</translation>
    </message>
    <message>
        <source>%1 has no geometry.</source>
        <translation>%1 hat keine Geometrie.</translation>
    </message>
    <message>
        <source>%1: the geometry has no type.</source>
        <translation>%1: Die Geometrie hat keinen Typ.</translation>
    </message>
    <message>
        <source>%1 is a %2; FloorCover reads plans drawn as polygons.</source>
        <translation>%1 ist ein %2; FloorCover liest Pläne, die als Polygone gezeichnet sind.</translation>
    </message>
    <message>
        <source>%1: the geometry holds no polygon outline.</source>
        <translation>%1: Die Geometrie enthält keinen Polygonumriss.</translation>
    </message>
    <message>
        <source>%1: the room name (properties.name) must be text, not %2.</source>
        <translation>%1: Der Raumname (properties.name) muss Text sein, nicht %2.</translation>
    </message>
    <message>
        <source>%1 has no name: rooms need one in properties.name.</source>
        <translation>%1 hat keinen Namen: Räume brauchen einen in properties.name.</translation>
    </message>
    <message>
        <source>The file holds %1 buildings (outer walls of %2 m², largest first), and a plan holds one: choose one as you open it.</source>
        <translation>Die Datei enthält %1 Gebäude (Außenwände von %2 m², das größte zuerst), ein Plan aber nur eines: wählen Sie eines beim Öffnen.</translation>
    </message>
    <message>
        <source>%1 has a hole; floor inside an obstacle is not supported.</source>
        <translation>%1 hat ein Loch; freie Fläche in einem Hindernis wird nicht unterstützt.</translation>
    </message>
    <message>
        <source>Two rooms are named “%1” (features %2 and %3): rename one.</source>
        <translation>Zwei Räume heißen „%1“ (Objekte %2 und %3): Benennen Sie einen davon um.</translation>
    </message>
    <message>
        <source>%1 has %2 separate parts: split it into rooms with names of their own.</source>
        <translation>%1 hat %2 getrennte Teile: Teilen Sie ihn in Räume mit eigenen Namen auf.</translation>
    </message>
    <message>
        <source>%1 has a hole: draw the hole as an obstacle instead.</source>
        <translation>%1 hat ein Loch: Zeichnen Sie das Loch stattdessen als Hindernis.</translation>
    </message>
    <message>
        <source>The file is not a GeoJSON FeatureCollection, the form in which FloorCover reads plans.</source>
        <translation>Die Datei ist keine GeoJSON-FeatureCollection, die Form, in der FloorCover Pläne liest.</translation>
    </message>
    <message>
        <source>The GeoJSON file has no list of features.</source>
        <translation>Die GeoJSON-Datei hat keine Liste von Objekten (features).</translation>
    </message>
    <message>
        <source>%1 is not a GeoJSON Feature.</source>
        <translation>%1 ist kein GeoJSON-Feature.</translation>
    </message>
    <message>
        <source>%1: its properties must be an object.</source>
        <translation>%1: Seine Eigenschaften (properties) müssen ein Objekt sein.</translation>
    </message>
    <message>
        <source>%1 has no role: set properties.role to boundary, obstacle or room.</source>
        <translation>%1 hat keine Rolle: Setzen Sie properties.role auf boundary, obstacle oder room.</translation>
    </message>
    <message>
        <source>%1: the role (properties.role) must be text, not %2.</source>
        <translation>%1: Die Rolle (properties.role) muss Text sein, nicht %2.</translation>
    </message>
    <message>
        <source>%1 has the unknown role “%2”: use boundary, obstacle or room.</source>
        <translation>%1 hat die unbekannte Rolle „%2“: Verwenden Sie boundary, obstacle oder room.</translation>
    </message>
    <message>
        <source>The plan has no outer wall: one feature needs properties.role = &quot;boundary&quot;.</source>
        <translation>Der Plan hat keine Außenwand: Ein Objekt braucht properties.role = &quot;boundary&quot;.</translation>
    </message>
    <message>
        <source>In the project file, %1 must be a finite number, not %2.</source>
        <translation>In der Projektdatei muss %1 eine endliche Zahl sein, nicht %2.</translation>
    </message>
    <message>
        <source>In the project file, %1 must be an object.</source>
        <translation>In der Projektdatei muss %1 ein Objekt sein.</translation>
    </message>
    <message>
        <source>In the project file, %1 must be [x, y] or null, not %2.</source>
        <translation>In der Projektdatei muss %1 [x, y] oder null sein, nicht %2.</translation>
    </message>
    <message>
        <source>In the project file, %1 has a coordinate that is not a finite number.</source>
        <translation>In der Projektdatei hat %1 eine Koordinate, die keine endliche Zahl ist.</translation>
    </message>
    <message>
        <source>The project&apos;s plan has no outer wall (boundary).</source>
        <translation>Der Plan des Projekts hat keine Außenwand (boundary).</translation>
    </message>
    <message>
        <source>In the project file, %1 must be a list.</source>
        <translation>In der Projektdatei muss %1 eine Liste sein.</translation>
    </message>
    <message>
        <source>%1 has no outline.</source>
        <translation>%1 hat keinen Umriss.</translation>
    </message>
    <message>
        <source>In the project file, plan.epsg must be an EPSG code (a positive whole number), not %1.</source>
        <translation>In der Projektdatei muss plan.epsg ein EPSG-Code sein (eine positive ganze Zahl), nicht %1.</translation>
    </message>
    <message>
        <source>The file is not a FloorCover project.</source>
        <translation>Die Datei ist kein FloorCover-Projekt.</translation>
    </message>
    <message>
        <source>The project file does not say its format version.</source>
        <translation>Die Projektdatei nennt ihre Formatversion nicht.</translation>
    </message>
    <message>
        <source>The project was saved by a newer FloorCover (format version %1; this one reads up to %2): update FloorCover.</source>
        <translation>Das Projekt wurde von einem neueren FloorCover gespeichert (Formatversion %1; dieses liest bis %2): Aktualisieren Sie FloorCover.</translation>
    </message>
    <message>
        <source>The project file has an invalid format version (%1).</source>
        <translation>Die Projektdatei hat eine ungültige Formatversion (%1).</translation>
    </message>
    <message>
        <source>The project file holds no plan.</source>
        <translation>Die Projektdatei enthält keinen Plan.</translation>
    </message>
    <message>
        <source>In the project file, sweep.%1 must be true or false.</source>
        <translation>In der Projektdatei muss sweep.%1 true oder false sein.</translation>
    </message>
    <message>
        <source>In the project file, sweep.room_angles must give each room&apos;s sweep angle in degrees.</source>
        <translation>In der Projektdatei muss sweep.room_angles für jeden Raum den Bahnwinkel in Grad angeben.</translation>
    </message>
    <message>
        <source>In the project file, the sweep angle of room “%1” must be a finite number of degrees, not %2.</source>
        <translation>In der Projektdatei muss der Bahnwinkel von Raum „%1“ eine endliche Gradzahl sein, nicht %2.</translation>
    </message>
    <message>
        <source>In the project file, solver must be the name of a solver, not %1.</source>
        <translation>In der Projektdatei muss solver der Name eines Lösers sein, nicht %1.</translation>
    </message>
    <message>
        <source>In the project file, selectedRooms must be a list of room names.</source>
        <translation>In der Projektdatei muss selectedRooms eine Liste von Raumnamen sein.</translation>
    </message>
    <message>
        <source>FloorCover cannot export to “%1” (it exports %2).</source>
        <translation>FloorCover kann nicht nach „%1“ exportieren (es exportiert %2).</translation>
    </message>
    <message>
        <source>FloorCover cannot export “%1”: it exports the path, the plan or the zones.</source>
        <translation>FloorCover kann „%1“ nicht exportieren: Es exportiert den Pfad, den Plan oder die Zonen.</translation>
    </message>
    <message>
        <source>The %1 format cannot hold the path: choose another format.</source>
        <translation>Das Format %1 kann den Pfad nicht aufnehmen: Wählen Sie ein anderes Format.</translation>
    </message>
    <message>
        <source>The %1 format cannot hold the plan: choose another format.</source>
        <translation>Das Format %1 kann den Plan nicht aufnehmen: Wählen Sie ein anderes Format.</translation>
    </message>
    <message>
        <source>The %1 format cannot hold the zones: choose another format.</source>
        <translation>Das Format %1 kann die Zonen nicht aufnehmen: Wählen Sie ein anderes Format.</translation>
    </message>
    <message>
        <source>FloorCover does not know this export format: choose one of the formats offered.</source>
        <translation>FloorCover kennt dieses Exportformat nicht: Wählen Sie eines der angebotenen Formate.</translation>
    </message>
    <message>
        <source>FloorCover cannot import “.%1” files (it imports %2).</source>
        <translation>FloorCover kann keine „.%1“-Dateien importieren (es importiert %2).</translation>
    </message>
    <message>
        <source>FloorCover cannot import “.%1” files.</source>
        <translation>FloorCover kann keine „.%1“-Dateien importieren.</translation>
    </message>
    <message>
        <source>“Close gaps up to” must be between 0 and 1000 m.</source>
        <translation>„Lücken schließen bis“ muss zwischen 0 und 1000 m liegen.</translation>
    </message>
    <message>
        <source>The plan needs repair (Plan &gt; Repair Plan, after the import): %1</source>
        <translation>Der Plan muss repariert werden (Planen &gt; Plan reparieren, nach dem Import): %1</translation>
    </message>
    <message>
        <source>The map&apos;s start pose (%1, %2) is not on the free floor; it was not used.</source>
        <translation>Die Startpose der Karte (%1, %2) liegt nicht auf der freien Fläche; sie wurde nicht verwendet.</translation>
    </message>
    <message>
        <source>The map image&apos;s pixels are %1; FloorCover reads 1- to 16-bit grey or colour images.</source>
        <translation>Die Pixel des Kartenbilds sind %1; FloorCover liest Grau- oder Farbbilder mit 1 bis 16 Bit.</translation>
    </message>
    <message>
        <source>The map image %1 is not a readable PNG, PGM, BMP or TIFF image.</source>
        <translation>Das Kartenbild %1 ist kein lesbares PNG-, PGM-, BMP- oder TIFF-Bild.</translation>
    </message>
    <message>
        <source>The map image is empty.</source>
        <translation>Das Kartenbild ist leer.</translation>
    </message>
    <message>
        <source>The map image has more than %1 pixels, more than FloorCover reads.</source>
        <translation>Das Kartenbild hat mehr als %1 Pixel, mehr als FloorCover liest.</translation>
    </message>
    <message>
        <source>The map image cannot be read (%1).</source>
        <translation>Das Kartenbild kann nicht gelesen werden (%1).</translation>
    </message>
    <message>
        <source>The map image uses a colour that its palette lacks.</source>
        <translation>Das Kartenbild verwendet eine Farbe, die in seiner Palette fehlt.</translation>
    </message>
    <message>
        <source>The map image %1 named in the YAML file is missing: keep it next to the YAML file.</source>
        <translation>Das in der YAML-Datei genannte Kartenbild %1 fehlt: Legen Sie es neben die YAML-Datei.</translation>
    </message>
    <message>
        <source>Every cell of the map is unknown: the map shows nothing.</source>
        <translation>Jede Zelle der Karte ist unbekannt: Die Karte zeigt nichts.</translation>
    </message>
    <message>
        <source>The map has no free floor.</source>
        <translation>Die Karte hat keine freie Fläche.</translation>
    </message>
    <message>
        <source>Cleaning the map left no free floor (its free cells are specks): lower “Drop islands below” under Clean the map.</source>
        <translation>Nach dem Bereinigen blieb keine freie Fläche (die freien Zellen der Karte sind Flecken): Verringern Sie „Inseln verwerfen unter“ unter Karte bereinigen.</translation>
    </message>
    <message>
        <source>The free floor is thinner than a pixel everywhere.</source>
        <translation>Die freie Fläche ist überall dünner als ein Pixel.</translation>
    </message>
    <message>
        <source>In the map&apos;s YAML file, %1 “%2” is not a number.</source>
        <translation>In der YAML-Datei der Karte ist %1 „%2“ keine Zahl.</translation>
    </message>
    <message>
        <source>In the map&apos;s YAML file, %1 must be a list [%2].</source>
        <translation>In der YAML-Datei der Karte muss %1 eine Liste [%2] sein.</translation>
    </message>
    <message>
        <source>In the map&apos;s YAML file, %1 needs %2 numbers, not %3.</source>
        <translation>In der YAML-Datei der Karte braucht %1 %2 Zahlen, nicht %3.</translation>
    </message>
    <message>
        <source>In the map&apos;s YAML file, %1 “%2” is not 0/1 or true/false.</source>
        <translation>In der YAML-Datei der Karte ist %1 „%2“ nicht 0/1 oder true/false.</translation>
    </message>
    <message>
        <source>The map&apos;s YAML file is larger than 1 MiB; a ROS map&apos;s is far smaller.</source>
        <translation>Die YAML-Datei der Karte ist größer als 1 MiB; die einer ROS-Karte ist viel kleiner.</translation>
    </message>
    <message>
        <source>Line %1 of the map&apos;s YAML file is not of the form “key: value”.</source>
        <translation>Zeile %1 der YAML-Datei der Karte hat nicht die Form „key: value“.</translation>
    </message>
    <message>
        <source>The YAML file names no image (image:): it is not a ROS map_server map.</source>
        <translation>Die YAML-Datei nennt kein Bild (image:): Sie ist keine Karte von ROS map_server.</translation>
    </message>
    <message>
        <source>The map&apos;s resolution is missing or not a positive size in metres.</source>
        <translation>Die Auflösung der Karte fehlt oder ist keine positive Größe in Metern.</translation>
    </message>
    <message>
        <source>A resolution of %1 m per cell is not an occupancy map&apos;s (1 mm to 1 m).</source>
        <translation>Eine Auflösung von %1 m je Zelle passt nicht zu einer Belegungskarte (1 mm bis 1 m).</translation>
    </message>
    <message>
        <source>The map has no origin [x, y, yaw].</source>
        <translation>Die Karte hat keinen Ursprung [x, y, yaw].</translation>
    </message>
    <message>
        <source>The map&apos;s origin [%1] lies far outside any map frame.</source>
        <translation>Der Ursprung der Karte [%1] liegt weit außerhalb jedes Kartenrahmens.</translation>
    </message>
    <message>
        <source>The map&apos;s thresholds must satisfy 0 ≤ free_thresh &lt; occupied_thresh ≤ 1.</source>
        <translation>Für die Schwellen der Karte muss 0 ≤ free_thresh &lt; occupied_thresh ≤ 1 gelten.</translation>
    </message>
    <message>
        <source>The map&apos;s mode “%1” is unknown: it must be trinary, scale or raw.</source>
        <translation>Der Modus „%1“ der Karte ist unbekannt: Er muss trinary, scale oder raw sein.</translation>
    </message>
    <message>
        <source>The map image is not a PGM or PBM image.</source>
        <translation>Das Kartenbild ist kein PGM- oder PBM-Bild.</translation>
    </message>
    <message>
        <source>In the PGM image&apos;s header, %1 “%2” is not a number.</source>
        <translation>Im Kopf des PGM-Bilds ist %1 „%2“ keine Zahl.</translation>
    </message>
    <message>
        <source>The PGM image&apos;s header has a bad size or maximum value.</source>
        <translation>Der Kopf des PGM-Bilds hat eine ungültige Größe oder einen ungültigen Höchstwert.</translation>
    </message>
    <message>
        <source>The %1 image&apos;s data is cut short or damaged.</source>
        <translation>Die Daten des %1-Bilds sind abgeschnitten oder beschädigt.</translation>
    </message>
    <message>
        <source>This FloorCover lacks GDAL&apos;s in-memory drivers: reinstall FloorCover.</source>
        <translation>Diesem FloorCover fehlen die Speicher-Treiber von GDAL: Installieren Sie FloorCover neu.</translation>
    </message>
    <message>
        <source>The map image does not fit in memory.</source>
        <translation>Das Kartenbild passt nicht in den Speicher.</translation>
    </message>
    <message>
        <source>The free floor falls into more than %1 pieces: clean the map more (Clean the map).</source>
        <translation>Die freie Fläche zerfällt in mehr als %1 Stücke: Bereinigen Sie die Karte stärker (Karte bereinigen).</translation>
    </message>
    <message>
        <source>Tracing the free floor failed (%1).</source>
        <translation>Das Nachzeichnen der freien Fläche ist fehlgeschlagen (%1).</translation>
    </message>
    <message>
        <source>Smoothing the outline of the free floor failed.</source>
        <translation>Das Glätten des Umrisses der freien Fläche ist fehlgeschlagen.</translation>
    </message>
    <message>
        <source>No free floor is left to import.</source>
        <translation>Es bleibt keine freie Fläche zum Importieren.</translation>
    </message>
    <message>
        <source>The obstacles could not be merged (their outlines are invalid).</source>
        <translation>Die Hindernisse ließen sich nicht vereinigen (ihre Umrisse sind ungültig).</translation>
    </message>
    <message>
        <source>The obstacles could not be cut out of the outer wall.</source>
        <translation>Die Hindernisse ließen sich nicht aus der Außenwand ausschneiden.</translation>
    </message>
    <message>
        <source>No closed outline for the outer wall; not closed: %1. A larger “Close gaps up to” may close them.</source>
        <translation>Kein geschlossener Umriss für die Außenwand; nicht geschlossen: %1. Ein größeres „Lücken schließen bis“ schließt sie vielleicht.</translation>
    </message>
    <message>
        <source>No closed outline for the outer wall: give the layer of the walls the role Boundary, or close its gaps with “Close gaps up to”.</source>
        <translation>Kein geschlossener Umriss für die Außenwand: Geben Sie dem Layer der Wände die Rolle Begrenzung oder schließen Sie seine Lücken mit „Lücken schließen bis“.</translation>
    </message>
    <message>
        <source>The plan has no outer wall to repair: draw one first.</source>
        <translation>Der Plan hat keine Außenwand, die repariert werden könnte: Zeichnen Sie zuerst eine.</translation>
    </message>
    <message>
        <source>The outer wall encloses no area.</source>
        <translation>Die Außenwand umschließt keine Fläche.</translation>
    </message>
    <message>
        <source>The outer wall crossed or touched itself: it was split there.</source>
        <translation>Die Außenwand kreuzte oder berührte sich selbst: Sie wurde dort geteilt.</translation>
    </message>
    <message>
        <source>Obstacles were merged, clipped to the outer wall or joined to it: %1 before, %2 after.</source>
        <translation>Hindernisse wurden vereinigt, an der Außenwand abgeschnitten oder mit ihr verbunden: %1 vorher, %2 nachher.</translation>
    </message>
    <message>
        <source>%1 lay outside the floor or under other rooms and was removed.</source>
        <translation>%1 lag außerhalb der Fläche oder unter anderen Räumen und wurde entfernt.</translation>
    </message>
    <message>
        <source>%1 was reshaped to fit the floor (%2 m² before, %3 m² after).</source>
        <translation>%1 wurde an die Fläche angepasst (%2 m² vorher, %3 m² nachher).</translation>
    </message>
    <message>
        <source>%1 was renamed “%2”.</source>
        <translation>%1 wurde in „%2“ umbenannt.</translation>
    </message>
    <message>
        <source>The WKT text begins with SRID= but has no “;” after the code.</source>
        <translation>Der WKT-Text beginnt mit SRID=, hat aber kein „;“ nach dem Code.</translation>
    </message>
    <message>
        <source>The SRID of the WKT text is not a number.</source>
        <translation>Die SRID des WKT-Texts ist keine Zahl.</translation>
    </message>
    <message>
        <source>The file is not valid WKT.</source>
        <translation>Die Datei ist kein gültiges WKT.</translation>
    </message>
    <message>
        <source>There is more text after the WKT geometry.</source>
        <translation>Nach der WKT-Geometrie folgt weiterer Text.</translation>
    </message>
    <message>
        <source>The WKT geometry is a %1, not a POLYGON or MULTIPOLYGON.</source>
        <translation>Die WKT-Geometrie ist ein %1, kein POLYGON oder MULTIPOLYGON.</translation>
    </message>
    <message>
        <source>The WKT polygon is empty.</source>
        <translation>Das WKT-Polygon ist leer.</translation>
    </message>
    <message>
        <source>The holes of polygon %1 (a room) were left out.</source>
        <translation>Die Löcher von Polygon %1 (ein Raum) wurden weggelassen.</translation>
    </message>
    <message>
        <source>The file is not a readable DXF drawing (%1).</source>
        <translation>Die Datei ist keine lesbare DXF-Zeichnung (%1).</translation>
    </message>
    <message>
        <source>The file is not a readable DXF drawing.</source>
        <translation>Die Datei ist keine lesbare DXF-Zeichnung.</translation>
    </message>
    <message>
        <source>The drawing has more than %1 vertices, more than FloorCover imports.</source>
        <translation>Die Zeichnung hat mehr als %1 Eckpunkte, mehr als FloorCover importiert.</translation>
    </message>
    <message>
        <source>The drawing has more than %1 open lines, more than FloorCover imports.</source>
        <translation>Die Zeichnung hat mehr als %1 offene Linien, mehr als FloorCover importiert.</translation>
    </message>
    <message>
        <source>The drawing has more than %1 entities, more than FloorCover imports.</source>
        <translation>Die Zeichnung hat mehr als %1 Elemente, mehr als FloorCover importiert.</translation>
    </message>
    <message>
        <source>A coordinate on layer “%1” is not a finite number.</source>
        <translation>Eine Koordinate auf Layer „%1“ ist keine endliche Zahl.</translation>
    </message>
    <message>
        <source>The drawing does not say its unit ($INSUNITS): it was read in metres; correct Units if it is not.</source>
        <translation>Die Zeichnung nennt ihre Einheit nicht ($INSUNITS): Sie wurde in Metern gelesen; korrigieren Sie Einheit, falls das nicht stimmt.</translation>
    </message>
    <message>
        <source>The drawing&apos;s unit ($INSUNITS %1) is unitless or unknown: it was read in metres; correct Units if it is not.</source>
        <translation>Die Einheit der Zeichnung ($INSUNITS %1) ist einheitenlos oder unbekannt: Sie wurde in Metern gelesen; korrigieren Sie Einheit, falls das nicht stimmt.</translation>
    </message>
    <message>
        <source>The drawing is empty.</source>
        <translation>Die Zeichnung ist leer.</translation>
    </message>
    <message>
        <source>The block leg must be a positive length in metres: change it in the Tiling Robot panel.</source>
        <translation>Die Blockkathete muss eine positive Länge in Metern sein: Ändern Sie sie im Bereich Kachelroboter.</translation>
    </message>
    <message>
        <source>Waypoints are exported as .csv or .json files, not as “%1”.</source>
        <translation>Wegpunkte werden als .csv- oder .json-Dateien exportiert, nicht als „%1“.</translation>
    </message>
    <message>
        <source>The exact ordering handles at most %1 waypoints, and this floor has %2: choose another ordering in the Tiling Robot panel.</source>
        <translation>Die exakte Reihenfolge schafft höchstens %1 Wegpunkte, diese Fläche hat %2: Wählen Sie im Bereich Kachelroboter eine andere Reihenfolge.</translation>
    </message>
    <message>
        <source>There is no ordering “%1” (available: %2).</source>
        <translation>Es gibt keine Reihenfolge „%1“ (verfügbar: %2).</translation>
    </message>
    <message>
        <source>%1 has too few different vertices (%2); an outline needs at least three.</source>
        <translation>%1 hat zu wenige verschiedene Eckpunkte (%2); ein Umriss braucht mindestens drei.</translation>
    </message>
    <message>
        <source>Pieces of floor not connected to the largest, left out: %1 (%2 m²).</source>
        <translation>Flächenstücke, die nicht mit dem größten verbunden sind, weggelassen: %1 (%2 m²).</translation>
    </message>
    <message>
        <source>Closed outlines outside the outer wall, left out: %1.</source>
        <translation>Geschlossene Umrisse außerhalb der Außenwand, weggelassen: %1.</translation>
    </message>
    <message>
        <source>Room outlines outside the outer wall, left out: %1.</source>
        <translation>Raumumrisse außerhalb der Außenwand, weggelassen: %1.</translation>
    </message>
    <message>
        <source>Obstacles without area, removed: %1.</source>
        <translation>Hindernisse ohne Fläche, entfernt: %1.</translation>
    </message>
    <message>
        <source>Obstacles that crossed themselves, split where they cross: %1.</source>
        <translation>Hindernisse, die sich selbst kreuzten, an den Kreuzungen geteilt: %1.</translation>
    </message>
    <message>
        <source>Entities left out on layer “%1” (its role is Ignored): %2.</source>
        <translation>Weggelassene Elemente auf Layer „%1“ (seine Rolle ist Ignoriert): %2.</translation>
    </message>
    <message>
        <source>Entities without usable 2D geometry, skipped: %1.</source>
        <translation>Elemente ohne verwendbare 2D-Geometrie, übersprungen: %1.</translation>
    </message>
    <message>
        <source>Open lines on layer “%1” that close into no outline, left out: %2 (%3 m); a larger “Close gaps up to” may close them.</source>
        <translation>Offene Linien auf Layer „%1“, die sich zu keinem Umriss schließen, weggelassen: %2 (%3 m); ein größeres „Lücken schließen bis“ schließt sie vielleicht.</translation>
    </message>
    <message>
        <source>The model is larger than FloorCover imports.</source>
        <translation>Das Modell ist größer, als FloorCover importiert.</translation>
    </message>
    <message>
        <source>FloorCover ran out of memory while reading the model: close other programs, or export a smaller part of the building.</source>
        <translation>FloorCover hatte beim Lesen des Modells nicht genug Speicher: Schließen Sie andere Programme oder exportieren Sie einen kleineren Teil des Gebäudes.</translation>
    </message>
    <message>
        <source>FloorCover imports 3D building models as .ifc, .obj, .gltf, .glb or .stl files, not as “%1” files.</source>
        <translation>FloorCover importiert 3D-Gebäudemodelle als .ifc-, .obj-, .gltf-, .glb- oder .stl-Dateien, nicht als „%1“-Dateien.</translation>
    </message>
    <message>
        <source>The model cannot be read (%1): export it again from the modelling program.</source>
        <translation>Das Modell kann nicht gelesen werden (%1): Exportieren Sie es erneut aus dem Modellierungsprogramm.</translation>
    </message>
    <message>
        <source>The model holds no 3D shapes (meshes) to cut: export it again with its geometry.</source>
        <translation>Das Modell enthält keine 3D-Formen (Meshes) zum Schneiden: Exportieren Sie es erneut mit seiner Geometrie.</translation>
    </message>
    <message>
        <source>The model holds no surfaces (triangles) to cut: export it again with its geometry.</source>
        <translation>Das Modell enthält keine Flächen (Dreiecke) zum Schneiden: Exportieren Sie es erneut mit seiner Geometrie.</translation>
    </message>
    <message>
        <source>The model has more than %1 triangles, more than FloorCover imports: export only the storey you need.</source>
        <translation>Das Modell hat mehr als %1 Dreiecke, mehr als FloorCover importiert: Exportieren Sie nur das Geschoss, das Sie brauchen.</translation>
    </message>
    <message>
        <source>The model&apos;s parts are nested more than %1 levels deep, more than FloorCover imports.</source>
        <translation>Die Teile des Modells sind mehr als %1 Ebenen tief verschachtelt, mehr als FloorCover importiert.</translation>
    </message>
    <message>
        <source>The model is damaged (its part “%1” refers to geometry that is missing): export it again.</source>
        <translation>Das Modell ist beschädigt (sein Teil „%1“ verweist auf fehlende Geometrie): Exportieren Sie es erneut.</translation>
    </message>
    <message>
        <source>The model&apos;s part “%1” has an invalid or huge coordinate: check the Unit in the Import 3D Building Model dialog.</source>
        <translation>Der Teil „%1“ des Modells hat eine ungültige oder riesige Koordinate: Prüfen Sie Einheit im Dialog 3D-Gebäudemodell importieren.</translation>
    </message>
    <message>
        <source>The unit must be a positive number of metres: choose another Unit in the Import 3D Building Model dialog.</source>
        <translation>Die Einheit muss eine positive Anzahl Meter sein: Wählen Sie im Dialog 3D-Gebäudemodell importieren eine andere Einheit.</translation>
    </message>
    <message>
        <source>“Cut above the floor” must be a positive number of metres.</source>
        <translation>„Schnitt über dem Boden“ muss eine positive Anzahl Meter sein.</translation>
    </message>
    <message>
        <source>The model has no storey “%1” (its storeys: %2): choose one under Storey.</source>
        <translation>Das Modell hat kein Geschoss „%1“ (seine Geschosse: %2): Wählen Sie eines unter Geschoss.</translation>
    </message>
    <message>
        <source>The cut at height %1 (%3 above the floor of storey “%2”) meets no wall: lower “Cut above the floor”, or check the Unit and the Storey.</source>
        <translation>Der Schnitt in Höhe %1 (%3 über dem Boden von Geschoss „%2“) trifft keine Wand: Verringern Sie „Schnitt über dem Boden“ oder prüfen Sie Einheit und Geschoss.</translation>
    </message>
    <message>
        <source>The cut at height %1 (%3 above the floor of storey “%2”) has more than %4 wall edges, more than FloorCover imports: try another “Cut above the floor”.</source>
        <translation>Der Schnitt in Höhe %1 (%3 über dem Boden von Geschoss „%2“) hat mehr als %4 Wandkanten, mehr als FloorCover importiert: Versuchen Sie einen anderen „Schnitt über dem Boden“.</translation>
    </message>
    <message>
        <source>The cut at height %1 (%3 above the floor of storey “%2”) encloses no free space: the outer walls are open at that height, or the model is not closed. Try another “Cut above the floor”.</source>
        <translation>Der Schnitt in Höhe %1 (%3 über dem Boden von Geschoss „%2“) umschließt keine freie Fläche: Die Außenwände sind in dieser Höhe offen, oder das Modell ist nicht geschlossen. Versuchen Sie einen anderen „Schnitt über dem Boden“.</translation>
    </message>
    <message>
        <source>The cut at height %1 (%3 above the floor of storey “%2”) makes no valid plan: %4</source>
        <translation>Der Schnitt in Höhe %1 (%3 über dem Boden von Geschoss „%2“) ergibt keinen gültigen Plan: %4</translation>
    </message>
    <message>
        <source>Smaller enclosed areas apart from the main floor, left out: %1 (%2 m² in all).</source>
        <translation>Kleinere umschlossene Flächen neben der Hauptfläche, weggelassen: %1 (%2 m² insgesamt).</translation>
    </message>
    <message>
        <source>Space “%1” has no closed outline at the cut height and is left out as a room.</source>
        <translation>Der Raum „%1“ hat in der Schnitthöhe keinen geschlossenen Umriss und wird als Raum weggelassen.</translation>
    </message>
    <message>
        <source>Room “%1” is left out: %2</source>
        <translation>Raum „%1“ wird weggelassen: %2</translation>
    </message>
    <message>
        <source>The map&apos;s rooms could not be separated: choose One room under “Split into rooms”, or another way to split.</source>
        <translation>Die Räume der Karte konnten nicht getrennt werden: Wählen Sie Ein Raum unter „In Räume teilen“ oder eine andere Aufteilung.</translation>
    </message>
    <message>
        <source>A speed of %1 m/s is not plausible for a robot (0.001 to 100 m/s): change it in the Planning panel.</source>
        <translation>Eine Geschwindigkeit von %1 m/s ist für einen Roboter nicht plausibel (0,001 bis 100 m/s): Ändern Sie sie im Bereich Planung.</translation>
    </message>
    <message>
        <source>A turn time of %1 s is not plausible (at most an hour per turn): change it in the Planning panel.</source>
        <translation>Eine Wendezeit von %1 s ist nicht plausibel (höchstens eine Stunde pro Wende): Ändern Sie sie im Bereich Planung.</translation>
    </message>
    <message>
        <source>%1: vertex %3 has a coordinate of %2 m, beyond the range of any map projection: is the plan in metres?</source>
        <translation>%1: Eckpunkt %3 hat eine Koordinate von %2 m, außerhalb des Bereichs jeder Kartenprojektion: Ist der Plan in Metern?</translation>
    </message>
    <message>
        <source>The boundary spans %1 km, more than the %2 km of any site on Earth: is the plan in metres?</source>
        <translation>Die Außenwand erstreckt sich über %1 km, mehr als die %2 km jedes Geländes auf der Erde: Ist der Plan in Metern?</translation>
    </message>
    <message>
        <source>The unit must be a positive number of metres below 1,000,000 (0.001 for a drawing in millimetres): correct Units in the import dialog.</source>
        <translation>Die Einheit muss eine positive Anzahl Meter unter 1.000.000 sein (0,001 für eine Zeichnung in Millimetern): Korrigieren Sie Einheit im Importdialog.</translation>
    </message>
    <message>
        <source>The file names EPSG code %1, which is not valid (codes run from 1 to %2).</source>
        <translation>Die Datei nennt den EPSG-Code %1, der ungültig ist (Codes reichen von 1 bis %2).</translation>
    </message>
    <message>
        <source>The point (%1, %2) in EPSG:%3 is not on the globe: are the coordinates in that system?</source>
        <translation>Der Punkt (%1, %2) in EPSG:%3 liegt nicht auf der Erdkugel: Sind die Koordinaten in diesem System?</translation>
    </message>
    <message>
        <source>The file is not JSON text (it holds a zero byte at offset %1): is it a binary file?</source>
        <translation>Die Datei ist kein JSON-Text (sie enthält ein Nullbyte an Position %1): Ist es eine Binärdatei?</translation>
    </message>
    <message>
        <source>“Fill notches up to” must be at most %1 m, not %2 m.</source>
        <translation>„Nischen füllen bis“ darf höchstens %1 m betragen, nicht %2 m.</translation>
    </message>
    <message>
        <source>“Remove obstacles up to” must be at most %1 m, not %2 m.</source>
        <translation>„Hindernisse entfernen bis“ darf höchstens %1 m betragen, nicht %2 m.</translation>
    </message>
    <message>
        <source>The floor would need about %1 tiles of a %2 m block leg, more than %3: choose a longer block leg.</source>
        <translation>Die Fläche bräuchte etwa %1 Kacheln mit %2 m Blockkathete, mehr als %3: Wählen Sie eine längere Blockkathete.</translation>
    </message>
    <message>
        <source>The block masses must be positive, at most 1,000,000 kg: change them in the Tiling Robot panel.</source>
        <translation>Die Blockmassen müssen positiv sein, höchstens 1.000.000 kg: Ändern Sie sie im Bereich Kachelroboter.</translation>
    </message>
    <message>
        <source>Obstacles that touched the outer wall or each other at a single point were shrunk by 1 mm.</source>
        <translation>Hindernisse, die die Außenwand oder einander in einem einzigen Punkt berührten, wurden um 1 mm verkleinert.</translation>
    </message>
</context>
<context>
    <name>fc::ui</name>
    <message>
        <source>Office floor</source>
        <translation>Büroetage</translation>
    </message>
    <message>
        <source>Twelve offices along a corridor</source>
        <translation>Zwölf Büros an einem Flur</translation>
    </message>
    <message>
        <source>Hospital ward</source>
        <translation>Krankenhausstation</translation>
    </message>
    <message>
        <source>Sixteen patient rooms with beds and a corridor</source>
        <translation>Sechzehn Patientenzimmer mit Betten und ein Flur</translation>
    </message>
    <message>
        <source>Room with a pillar</source>
        <translation>Raum mit Säule</translation>
    </message>
    <message>
        <source>One room with an obstacle in it</source>
        <translation>Ein Raum mit einem Hindernis darin</translation>
    </message>
    <message>
        <source>Room with notches</source>
        <translation>Raum mit Nischen</translation>
    </message>
    <message>
        <source>One room whose walls have recesses</source>
        <translation>Ein Raum mit Nischen in den Wänden</translation>
    </message>
    <message>
        <source>Slanted room</source>
        <translation>Schräger Raum</translation>
    </message>
    <message>
        <source>A room drawn at an angle, with an obstacle</source>
        <translation>Ein schräg gezeichneter Raum mit einem Hindernis</translation>
    </message>
    <message>
        <source>Simple room</source>
        <translation>Einfacher Raum</translation>
    </message>
    <message>
        <source>The smallest example: one room, one obstacle</source>
        <translation>Das kleinste Beispiel: ein Raum, ein Hindernis</translation>
    </message>
</context>
<context>
    <name>fc::ui::BuildingImportDialog</name>
    <message>
        <source>File&apos;s unit</source>
        <translation>Einheit der Datei</translation>
    </message>
    <message>
        <source>Metres</source>
        <translation>Meter</translation>
    </message>
    <message>
        <source>Centimetres</source>
        <translation>Zentimeter</translation>
    </message>
    <message>
        <source>Millimetres</source>
        <translation>Millimeter</translation>
    </message>
    <message>
        <source>Feet</source>
        <translation>Fuß</translation>
    </message>
    <message>
        <source>Inches</source>
        <translation>Zoll</translation>
    </message>
    <message>
        <source>Door leaves do not block</source>
        <translation>Türblätter blockieren nicht</translation>
    </message>
    <message>
        <source>Import 3D Building Model — %1</source>
        <translation>3D-Gebäudemodell importieren – %1</translation>
    </message>
    <message>
        <source> m</source>
        <translation> m</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>Automatisch</translation>
    </message>
    <message>
        <source>Y up</source>
        <translation>Y oben</translation>
    </message>
    <message>
        <source>Z up</source>
        <translation>Z oben</translation>
    </message>
    <message>
        <source>Storey:</source>
        <translation>Geschoss:</translation>
    </message>
    <message>
        <source>Cut above the floor:</source>
        <translation>Schnitt über dem Boden:</translation>
    </message>
    <message>
        <source>Unit:</source>
        <translation>Einheit:</translation>
    </message>
    <message>
        <source>Up axis:</source>
        <translation>Hochachse:</translation>
    </message>
    <message>
        <source>%1 obstacles, %2 rooms</source>
        <translation>%1 Hindernisse, %2 Räume</translation>
    </message>
</context>
<context>
    <name>fc::ui::CanvasView</name>
    <message>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <source>%1 cm</source>
        <translation>%1 cm</translation>
    </message>
</context>
<context>
    <name>fc::ui::CompareDialog</name>
    <message>
        <source>Planning with every solver…</source>
        <translation>Planung mit jedem Löser…</translation>
    </message>
    <message>
        <source>Compare Solvers</source>
        <translation>Löser vergleichen</translation>
    </message>
    <message>
        <source>Solver</source>
        <translation>Löser</translation>
    </message>
    <message>
        <source>Length (m)</source>
        <translation>Länge (m)</translation>
    </message>
    <message>
        <source>Extra (m)</source>
        <translation>Zusätzlich (m)</translation>
    </message>
    <message>
        <source>Turns</source>
        <translation>Wendungen</translation>
    </message>
    <message>
        <source>Coverage</source>
        <translation>Abdeckung</translation>
    </message>
    <message>
        <source>Time (s)</source>
        <translation>Zeit (s)</translation>
    </message>
    <message>
        <source>Planning (s)</source>
        <translation>Planung (s)</translation>
    </message>
    <message>
        <source>%1 of %2 solvers answered; overlaps are drawn in blue.</source>
        <translation>%1 von %2 Lösern haben geantwortet; Überlappungen sind blau gezeichnet.</translation>
    </message>
    <message>
        <source>Comparing the solvers</source>
        <translation>Löser werden verglichen</translation>
    </message>
    <message>
        <source>Planning with every solver… (%1)</source>
        <translation>Planung mit jedem Löser… (%1)</translation>
    </message>
    <message>
        <source>The comparison failed: %1</source>
        <translation>Der Vergleich ist fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>The comparison was cancelled.</source>
        <translation>Der Vergleich wurde abgebrochen.</translation>
    </message>
    <message>
        <source>The method that ordered the rooms&apos; cells</source>
        <translation>Das Verfahren, das die Zellen der Räume geordnet hat</translation>
    </message>
    <message>
        <source>How far the robot drives in all</source>
        <translation>Wie weit der Roboter insgesamt fährt</translation>
    </message>
    <message>
        <source>Distance beyond the stripes themselves (floor area / coverage width): the moves between stripes and rooms. Less is better.</source>
        <translation>Strecke über die Bahnen selbst hinaus (Bodenfläche / Arbeitsbreite): die Fahrten zwischen Bahnen und Räumen. Weniger ist besser.</translation>
    </message>
    <message>
        <source>Turns the robot makes; each costs the turn time</source>
        <translation>Wendungen des Roboters; jede kostet die Wendezeit</translation>
    </message>
    <message>
        <source>Share of the floor the robot can reach that the path sweeps</source>
        <translation>Anteil des erreichbaren Bodens, den der Pfad überstreicht</translation>
    </message>
    <message>
        <source>Estimated cleaning time: length / speed + turns × turn time</source>
        <translation>Geschätzte Reinigungszeit: Länge / Geschwindigkeit + Wendungen × Wendezeit</translation>
    </message>
    <message>
        <source>How long the computer took to plan</source>
        <translation>Wie lange der Rechner zum Planen brauchte</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Anhalten</translation>
    </message>
    <message>
        <source>Stop comparing; solvers that answered stay in the table</source>
        <translation>Vergleich anhalten; Löser, die geantwortet haben, bleiben in der Tabelle</translation>
    </message>
    <message>
        <source>Did not plan: %1</source>
        <translation>Nicht geplant: %1</translation>
    </message>
    <message>
        <source>%1 drives %3 % of the extra distance of %2 (a published method) and makes %4 % of its turns; below 100 % is better. The published comparison: %5.</source>
        <translation>%1 fährt %3 % der Zusatzstrecke von %2 (einem veröffentlichten Verfahren) und macht %4 % seiner Wendungen; unter 100 % ist besser. Der veröffentlichte Vergleich: %5.</translation>
    </message>
    <message>
        <source>Close; a comparison still running is cancelled at once</source>
        <translation>Schließen; ein noch laufender Vergleich wird sofort abgebrochen</translation>
    </message>
    <message>
        <source>One row per solver; hover a column&apos;s title for what it means.</source>
        <translation>Eine Zeile je Löser; zeigen Sie auf eine Spaltenüberschrift, um zu sehen, was sie bedeutet.</translation>
    </message>
</context>
<context>
    <name>fc::ui::Document</name>
    <message>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <source>Draw the boundary first: obstacles and rooms must lie inside it.</source>
        <translation>Zeichnen Sie zuerst die Außenwand: Hindernisse und Räume müssen darin liegen.</translation>
    </message>
    <message>
        <source>Room %1</source>
        <translation>Raum %1</translation>
    </message>
    <message>
        <source>Add boundary</source>
        <translation>Außenwand hinzufügen</translation>
    </message>
    <message>
        <source>Replace boundary</source>
        <translation>Außenwand ersetzen</translation>
    </message>
    <message>
        <source>Add obstacle</source>
        <translation>Hindernis hinzufügen</translation>
    </message>
    <message>
        <source>Add room %1</source>
        <translation>Raum %1 hinzufügen</translation>
    </message>
    <message>
        <source>Move vertex</source>
        <translation>Eckpunkt verschieben</translation>
    </message>
    <message>
        <source>Insert vertex</source>
        <translation>Eckpunkt einfügen</translation>
    </message>
    <message>
        <source>A polygon needs at least three vertices; delete the polygon instead.</source>
        <translation>Ein Polygon braucht mindestens drei Eckpunkte; löschen Sie stattdessen das Polygon.</translation>
    </message>
    <message>
        <source>Delete vertex</source>
        <translation>Eckpunkt löschen</translation>
    </message>
    <message>
        <source>Delete the obstacles and rooms before the boundary.</source>
        <translation>Löschen Sie die Hindernisse und Räume vor der Außenwand.</translation>
    </message>
    <message>
        <source>Delete boundary</source>
        <translation>Außenwand löschen</translation>
    </message>
    <message>
        <source>Delete obstacle</source>
        <translation>Hindernis löschen</translation>
    </message>
    <message>
        <source>Delete room %1</source>
        <translation>Raum %1 löschen</translation>
    </message>
    <message>
        <source>There is no room %1.</source>
        <translation>Es gibt keinen Raum %1.</translation>
    </message>
    <message>
        <source>A room needs a name.</source>
        <translation>Ein Raum braucht einen Namen.</translation>
    </message>
    <message>
        <source>There is already a room named &quot;%1&quot;.</source>
        <translation>Es gibt schon einen Raum namens „%1“.</translation>
    </message>
    <message>
        <source>Rename room %1 to %2</source>
        <translation>Raum %1 in %2 umbenennen</translation>
    </message>
    <message>
        <source>Change robot profile</source>
        <translation>Roboterprofil ändern</translation>
    </message>
    <message>
        <source>The sweep angle must be a finite number of degrees.</source>
        <translation>Der Bahnwinkel muss eine endliche Gradzahl sein.</translation>
    </message>
    <message>
        <source>Change sweep angle</source>
        <translation>Bahnwinkel ändern</translation>
    </message>
    <message>
        <source>Choose solver %1</source>
        <translation>Löser %1 wählen</translation>
    </message>
    <message>
        <source>Place start</source>
        <translation>Start setzen</translation>
    </message>
    <message>
        <source>Remove start</source>
        <translation>Start entfernen</translation>
    </message>
    <message>
        <source>Place end</source>
        <translation>Ziel setzen</translation>
    </message>
    <message>
        <source>Remove end</source>
        <translation>Ziel entfernen</translation>
    </message>
    <message>
        <source>There is no room named &quot;%1&quot;.</source>
        <translation>Es gibt keinen Raum namens „%1“.</translation>
    </message>
    <message>
        <source>At least one room must stay selected for planning.</source>
        <translation>Mindestens ein Raum muss für die Planung ausgewählt bleiben.</translation>
    </message>
    <message>
        <source>Deselect room %1</source>
        <translation>Raum %1 abwählen</translation>
    </message>
    <message>
        <source>Select room %1</source>
        <translation>Raum %1 auswählen</translation>
    </message>
    <message>
        <source>There is no such polygon.</source>
        <translation>Dieses Polygon gibt es nicht.</translation>
    </message>
    <message>
        <source>There is no such vertex.</source>
        <translation>Diesen Eckpunkt gibt es nicht.</translation>
    </message>
    <message>
        <source>Choose two different rooms to merge.</source>
        <translation>Wählen Sie zwei verschiedene Räume zum Zusammenführen.</translation>
    </message>
    <message>
        <source>%1 and %2 cannot be merged: %3</source>
        <translation>%1 und %2 lassen sich nicht zusammenführen: %3</translation>
    </message>
    <message>
        <source>Merge rooms %1 and %2</source>
        <translation>Räume %1 und %2 zusammenführen</translation>
    </message>
    <message>
        <source>%1 cannot be split: %2</source>
        <translation>%1 lässt sich nicht teilen: %2</translation>
    </message>
    <message>
        <source>Split room %1 (new room %2)</source>
        <translation>Raum %1 teilen (neuer Raum %2)</translation>
    </message>
    <message>
        <source>The plan cannot be repaired automatically: %1</source>
        <translation>Der Plan lässt sich nicht automatisch reparieren: %1</translation>
    </message>
    <message>
        <source>The automatic repair left a problem: %1</source>
        <translation>Nach der automatischen Reparatur bleibt ein Problem: %1</translation>
    </message>
    <message>
        <source>Repair plan</source>
        <translation>Plan reparieren</translation>
    </message>
    <message>
        <source>This plan has problems (see the Problems panel): repair it first with Plan &gt; Repair Plan, or undo back to a valid plan.</source>
        <translation>Dieser Plan hat Probleme (siehe Bereich Probleme): Reparieren Sie ihn zuerst mit Planen &gt; Plan reparieren oder machen Sie Änderungen bis zu einem gültigen Plan rückgängig.</translation>
    </message>
</context>
<context>
    <name>fc::ui::DocumentFiles</name>
    <message>
        <source>Cannot save %1: %2</source>
        <translation>%1 kann nicht gespeichert werden: %2</translation>
    </message>
</context>
<context>
    <name>fc::ui::DrawPolygonTool</name>
    <message>
        <source>Draw Boundary</source>
        <translation>Außenwand zeichnen</translation>
    </message>
    <message>
        <source>Draw Obstacle</source>
        <translation>Hindernis zeichnen</translation>
    </message>
    <message>
        <source>Draw Room</source>
        <translation>Raum zeichnen</translation>
    </message>
    <message>
        <source>%1: click vertices and click the first one to close, or drag a rectangle. Shift keeps right angles, Backspace removes a vertex, Esc cancels.</source>
        <translation>%1: Eckpunkte anklicken und zum Schließen den ersten erneut anklicken, oder ein Rechteck aufziehen. Umschalt hält rechte Winkel, Rücktaste entfernt einen Eckpunkt, Esc bricht ab.</translation>
    </message>
    <message>
        <source>A polygon needs at least three vertices.</source>
        <translation>Ein Polygon braucht mindestens drei Eckpunkte.</translation>
    </message>
    <message>
        <source>%1 refused: %2</source>
        <translation>%1 abgelehnt: %2</translation>
    </message>
    <message>
        <source>Kept the existing boundary.</source>
        <translation>Die bestehende Begrenzung bleibt.</translation>
    </message>
    <message>
        <source>The plan already has a boundary, and a plan has only one. Replace it with the one you drew? (Undo brings the old boundary back.)</source>
        <translation>Der Plan hat schon eine Begrenzung, und ein Plan hat nur eine. Durch die gezeichnete ersetzen? (Rückgängig holt die alte Begrenzung zurück.)</translation>
    </message>
</context>
<context>
    <name>fc::ui::EditVerticesTool</name>
    <message>
        <source>Edit Vertices</source>
        <translation>Eckpunkte bearbeiten</translation>
    </message>
    <message>
        <source>Edit Vertices: drag a vertex to move it, double-click an edge to add one, right-click a vertex to delete it; select a polygon and press Delete to delete it.</source>
        <translation>Eckpunkte bearbeiten: Eckpunkt ziehen zum Verschieben, Kante doppelklicken zum Einfügen, Rechtsklick auf einen Eckpunkt zum Löschen; ein Polygon auswählen und Entf drücken, um es zu löschen.</translation>
    </message>
</context>
<context>
    <name>fc::ui::HelpDialog</name>
    <message>
        <source>Getting Started with FloorCover</source>
        <translation>Erste Schritte mit FloorCover</translation>
    </message>
    <message>
        <source>Close the guide</source>
        <translation>Anleitung schließen</translation>
    </message>
</context>
<context>
    <name>fc::ui::ImportDialog</name>
    <message>
        <source>Boundary</source>
        <translation>Begrenzung</translation>
    </message>
    <message>
        <source>Obstacles</source>
        <translation>Hindernisse</translation>
    </message>
    <message>
        <source>Rooms</source>
        <translation>Räume</translation>
    </message>
    <message>
        <source>Ignored</source>
        <translation>Ignoriert</translation>
    </message>
    <message>
        <source>Auto (by shape)</source>
        <translation>Automatisch (nach Form)</translation>
    </message>
    <message>
        <source>Open as a new document</source>
        <translation>Als neues Dokument öffnen</translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation>%1 importieren</translation>
    </message>
    <message>
        <source>Layer</source>
        <translation>Layer</translation>
    </message>
    <message>
        <source>Role</source>
        <translation>Rolle</translation>
    </message>
    <message>
        <source> m per unit</source>
        <translation> m pro Einheit</translation>
    </message>
    <message>
        <source> m</source>
        <translation> m</translation>
    </message>
    <message>
        <source>Units:</source>
        <translation>Einheit:</translation>
    </message>
    <message>
        <source>Close gaps up to:</source>
        <translation>Lücken schließen bis:</translation>
    </message>
    <message>
        <source>Free area %1 m², %2 obstacles, %3 rooms</source>
        <translation>Freie Fläche %1 m², %2 Hindernisse, %3 Räume</translation>
    </message>
    <message>
        <source>Clean the map</source>
        <translation>Karte bereinigen</translation>
    </message>
    <message>
        <source>Walls</source>
        <translation>Wände</translation>
    </message>
    <message>
        <source>Floor</source>
        <translation>Boden</translation>
    </message>
    <message>
        <source> m²</source>
        <translation> m²</translation>
    </message>
    <message>
        <source>Obstacle specks smaller than this become floor (sensor noise)</source>
        <translation>Hindernisflecken unter dieser Größe werden Boden (Sensorrauschen)</translation>
    </message>
    <message>
        <source>Free islands smaller than this are dropped</source>
        <translation>Freie Inseln unter dieser Größe werden verworfen</translation>
    </message>
    <message>
        <source>Notches and slivers narrower than twice this are filled (the robot&apos;s radius: what its body cannot enter)</source>
        <translation>Nischen und Spalten schmaler als das Doppelte werden gefüllt (der Roboterradius: wohin sein Körper nicht passt)</translation>
    </message>
    <message>
        <source>Obstacles thinner than twice this vanish (0: off; thin walls too)</source>
        <translation>Hindernisse dünner als das Doppelte verschwinden (0: aus; auch dünne Wände)</translation>
    </message>
    <message>
        <source>Along the map&apos;s two main directions</source>
        <translation>Entlang der zwei Hauptrichtungen der Karte</translation>
    </message>
    <message>
        <source>Each ragged wall becomes one line within a cell of its scan, so the path runs along it instead of zigzagging</source>
        <translation>Jede ausgefranste Wand wird eine Linie innerhalb einer Zelle ihres Scans, sodass der Pfad an ihr entlang läuft statt im Zickzack</translation>
    </message>
    <message>
        <source>Notches in a straightened wall up to this deep are filled</source>
        <translation>Nischen in einer begradigten Wand bis zu dieser Tiefe werden gefüllt</translation>
    </message>
    <message>
        <source>At doorways (distance)</source>
        <translation>An Türen (Abstand)</translation>
    </message>
    <message>
        <source>At doorways (morphological)</source>
        <translation>An Türen (morphologisch)</translation>
    </message>
    <message>
        <source>One room</source>
        <translation>Ein Raum</translation>
    </message>
    <message>
        <source>Smaller rooms (alcoves, door recesses) join a neighbour</source>
        <translation>Kleinere Räume (Nischen, Türlaibungen) gehen im Nachbarraum auf</translation>
    </message>
    <message>
        <source>Unknown cells are:</source>
        <translation>Unbekannte Zellen sind:</translation>
    </message>
    <message>
        <source>Remove specks below:</source>
        <translation>Flecken entfernen unter:</translation>
    </message>
    <message>
        <source>Drop islands below:</source>
        <translation>Inseln verwerfen unter:</translation>
    </message>
    <message>
        <source>Fill notches up to:</source>
        <translation>Nischen füllen bis:</translation>
    </message>
    <message>
        <source>Remove obstacles up to:</source>
        <translation>Hindernisse entfernen bis:</translation>
    </message>
    <message>
        <source>Straighten walls:</source>
        <translation>Wände begradigen:</translation>
    </message>
    <message>
        <source>Fill notches in straight walls up to:</source>
        <translation>Nischen in geraden Wänden füllen bis:</translation>
    </message>
    <message>
        <source>Split into rooms:</source>
        <translation>In Räume teilen:</translation>
    </message>
    <message>
        <source>Smallest room:</source>
        <translation>Kleinster Raum:</translation>
    </message>
    <message>
        <source>Cleaning removed %1 specks (%2 m²) and %3 free islands (%4 m²); filling notches took %5 m², removing thin obstacles gave %6 m².</source>
        <translation>Die Bereinigung entfernte %1 Flecken (%2 m²) und %3 freie Inseln (%4 m²); das Füllen von Nischen nahm %5 m², das Entfernen dünner Hindernisse gab %6 m².</translation>
    </message>
    <message>
        <source>%1 walls straightened at %2°: %3 m² of floor gained, %4 m² lost (%5 notches filled); %6 unknown gaps became floor.</source>
        <translation>%1 Wände bei %2° begradigt: %3 m² Boden gewonnen, %4 m² verloren (%5 Nischen gefüllt); %6 unbekannte Lücken wurden Boden.</translation>
    </message>
    <message>
        <source>The drawing&apos;s layers: choose what each holds (walls, obstacles, rooms, or nothing to import).</source>
        <translation>Die Layer der Zeichnung: Wählen Sie, was jeder enthält (Wände, Hindernisse, Räume oder nichts zum Importieren).</translation>
    </message>
    <message>
        <source>How many metres one drawing unit is (0.001 for a drawing in mm).</source>
        <translation>Wie viele Meter eine Zeichnungseinheit ist (0,001 für eine Zeichnung in mm).</translation>
    </message>
    <message>
        <source>Lines whose ends are at most this far apart are joined into closed outlines.</source>
        <translation>Linien, deren Enden höchstens so weit auseinanderliegen, werden zu geschlossenen Umrissen verbunden.</translation>
    </message>
    <message>
        <source>What the import left out or guessed, and why.</source>
        <translation>Was der Import ausgelassen oder geschätzt hat, und warum.</translation>
    </message>
    <message>
        <source>Open the import as its own document instead of replacing the plan of the current one.</source>
        <translation>Den Import als eigenes Dokument öffnen, statt den Plan des aktuellen Dokuments zu ersetzen.</translation>
    </message>
    <message>
        <source>What the map&apos;s unknown (grey) cells are: walls, or floor the robot may clean.</source>
        <translation>Was die unbekannten (grauen) Zellen der Karte sind: Wände oder Boden, den der Roboter reinigen darf.</translation>
    </message>
    <message>
        <source>How the map&apos;s free space is split into rooms: at doorways (two methods), or kept as one room.</source>
        <translation>Wie die freie Fläche der Karte in Räume geteilt wird: an Türen (zwei Verfahren) oder als ein einziger Raum.</translation>
    </message>
    <message>
        <source>What layer %1 holds</source>
        <translation>Was Layer %1 enthält</translation>
    </message>
    <message numerus="yes">
        <source>Obstacles joined to their neighbours across gaps narrower than the robot: %n (%1 m²).</source>
        <translation>
            <numerusform>Über Lücken, schmaler als der Roboter, mit Nachbarn verbundene Hindernisse: %n (%1 m²).</numerusform>
            <numerusform>Über Lücken, schmaler als der Roboter, mit Nachbarn verbundene Hindernisse: %n (%1 m²).</numerusform>
        </translation>
    </message>
    <message>
        <source>Building:</source>
        <translation>Gebäude:</translation>
    </message>
    <message>
        <source>The file holds several buildings (outer walls); a plan holds one. Largest first.</source>
        <translation>Die Datei enthält mehrere Gebäude (Außenwände); ein Plan enthält eines. Das größte zuerst.</translation>
    </message>
    <message numerus="yes">
        <source>Doorway borders between rooms laid along the walls: %n.</source>
        <translation>
            <numerusform>Türdurchgangsgrenzen zwischen Räumen an die Wände gelegt: %n.</numerusform>
            <numerusform>Türdurchgangsgrenzen zwischen Räumen an die Wände gelegt: %n.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>fc::ui::LegendDock</name>
    <message>
        <source>Legend</source>
        <translation>Legende</translation>
    </message>
    <message>
        <source>Transit</source>
        <translation>Leerfahrt</translation>
    </message>
    <message>
        <source>Moves between cells and rooms without cleaning (part of the Path)</source>
        <translation>Fahrten zwischen Zellen und Räumen ohne Reinigung (Teil des Pfads)</translation>
    </message>
    <message>
        <source>S</source>
        <translation>S</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>Where the robot starts: yours, or the planner&apos;s choice when none is placed</source>
        <translation>Wo der Roboter startet: Ihr gesetzter Start oder, wenn keiner gesetzt ist, die Wahl des Planers</translation>
    </message>
    <message>
        <source>E</source>
        <translation>Z</translation>
    </message>
    <message>
        <source>End</source>
        <translation>Ziel</translation>
    </message>
    <message>
        <source>Where the path ends</source>
        <translation>Wo der Pfad endet</translation>
    </message>
</context>
<context>
    <name>fc::ui::MainWindow</name>
    <message>
        <source>Tools</source>
        <translation>Werkzeuge</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederherstellen</translation>
    </message>
    <message>
        <source>&amp;Preferences…</source>
        <translation>&amp;Einstellungen…</translation>
    </message>
    <message>
        <source>&amp;Tools</source>
        <translation>&amp;Werkzeuge</translation>
    </message>
    <message>
        <source>&amp;Plan</source>
        <translation>&amp;Planen</translation>
    </message>
    <message>
        <source>&amp;Plan Path</source>
        <translation>&amp;Pfad planen</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>&amp;About FloorCover</source>
        <translation>&amp;Über FloorCover</translation>
    </message>
    <message>
        <source>About FloorCover</source>
        <translation>Über FloorCover</translation>
    </message>
    <message>
        <source>FloorCover %1
Coverage path planning for cleaning and disinfection robots.</source>
        <translation>FloorCover %1
Abdeckungspfadplanung für Reinigungs- und Desinfektionsroboter.</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>&amp;Fit to Plan</source>
        <translation>&amp;Plan einpassen</translation>
    </message>
    <message>
        <source>Zoom &amp;In</source>
        <translation>Ver&amp;größern</translation>
    </message>
    <message>
        <source>Zoom &amp;Out</source>
        <translation>Ver&amp;kleinern</translation>
    </message>
    <message>
        <source>Show &amp;Grid</source>
        <translation>&amp;Raster anzeigen</translation>
    </message>
    <message>
        <source>Snap to G&amp;rid</source>
        <translation>Am Ra&amp;ster fangen</translation>
    </message>
    <message>
        <source>Snap to &amp;Vertices</source>
        <translation>An &amp;Eckpunkten fangen</translation>
    </message>
    <message>
        <source>&amp;Overlays</source>
        <translation>Ü&amp;berlagerungen</translation>
    </message>
    <message>
        <source>x %1 m   y %2 m</source>
        <translation>x %1 m   y %2 m</translation>
    </message>
    <message>
        <source>%1[*] – FloorCover</source>
        <translation>%1[*] – FloorCover</translation>
    </message>
    <message>
        <source>FloorCover</source>
        <translation>FloorCover</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <source>%1 has unsaved changes. Save them?</source>
        <translation>%1 hat ungespeicherte Änderungen. Speichern?</translation>
    </message>
    <message>
        <source>Recover unsaved changes</source>
        <translation>Ungespeicherte Änderungen wiederherstellen</translation>
    </message>
    <message>
        <source>Recovered the unsaved changes of the last session.</source>
        <translation>Die ungespeicherten Änderungen der letzten Sitzung wurden wiederhergestellt.</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>%1 geöffnet</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>&amp;Neu</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>Ö&amp;ffnen…</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>Speichern &amp;unter…</translation>
    </message>
    <message>
        <source>&amp;Export Path…</source>
        <translation>Pfad &amp;exportieren…</translation>
    </message>
    <message>
        <source>Export View as &amp;PNG…</source>
        <translation>Ansicht als &amp;PNG exportieren…</translation>
    </message>
    <message>
        <source>Export View as S&amp;VG…</source>
        <translation>Ansicht als S&amp;VG exportieren…</translation>
    </message>
    <message>
        <source>Export &amp;Report as PDF…</source>
        <translation>&amp;Bericht als PDF exportieren…</translation>
    </message>
    <message>
        <source>Export Report</source>
        <translation>Bericht exportieren</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>Open Plan</source>
        <translation>Plan öffnen</translation>
    </message>
    <message>
        <source>Plans and projects (*.fcproj *.geojson *.json);;FloorCover projects (*.fcproj);;GeoJSON plans (*.geojson *.json)</source>
        <translation>Pläne und Projekte (*.fcproj *.geojson *.json);;FloorCover-Projekte (*.fcproj);;GeoJSON-Pläne (*.geojson *.json)</translation>
    </message>
    <message>
        <source>Save Project</source>
        <translation>Projekt speichern</translation>
    </message>
    <message>
        <source>FloorCover projects (*.fcproj)</source>
        <translation>FloorCover-Projekte (*.fcproj)</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <source>There is no path to export: plan the current document first.</source>
        <translation>Es gibt keinen Pfad zum Exportieren: Planen Sie zuerst das aktuelle Dokument.</translation>
    </message>
    <message>
        <source>Floor plan exported by FloorCover</source>
        <translation>Grundriss, exportiert von FloorCover</translation>
    </message>
    <message>
        <source>Cannot write %1.</source>
        <translation>%1 kann nicht geschrieben werden.</translation>
    </message>
    <message>
        <source>Exported the view to %1</source>
        <translation>Ansicht nach %1 exportiert</translation>
    </message>
    <message>
        <source>SVG images (*.svg)</source>
        <translation>SVG-Bilder (*.svg)</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>PNG-Bilder (*.png)</translation>
    </message>
    <message>
        <source>Export View</source>
        <translation>Ansicht exportieren</translation>
    </message>
    <message>
        <source>There is no plan to report: plan the current document first.</source>
        <translation>Es gibt keinen Plan für einen Bericht: Planen Sie zuerst das aktuelle Dokument.</translation>
    </message>
    <message>
        <source>Exported the report to %1</source>
        <translation>Bericht nach %1 exportiert</translation>
    </message>
    <message>
        <source>planning failed: %1</source>
        <translation>Planung fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>cannot write %1</source>
        <translation>%1 kann nicht geschrieben werden</translation>
    </message>
    <message>
        <source>History</source>
        <translation>Verlauf</translation>
    </message>
    <message>
        <source>&amp;Compare Solvers…</source>
        <translation>Löser &amp;vergleichen…</translation>
    </message>
    <message>
        <source>&amp;Import…</source>
        <translation>&amp;Importieren…</translation>
    </message>
    <message>
        <source>Import Plan</source>
        <translation>Plan importieren</translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation>%1 importieren</translation>
    </message>
    <message numerus="yes">
        <source>Imported %1 (%n warning(s))</source>
        <translation>
            <numerusform>%1 importiert (%n Warnung)</numerusform>
            <numerusform>%1 importiert (%n Warnungen)</numerusform>
        </translation>
    </message>
    <message>
        <source>Cannot export the path to %1: unknown file extension</source>
        <translation>Der Pfad kann nicht nach %1 exportiert werden: unbekannte Dateiendung</translation>
    </message>
    <message>
        <source>Cannot export to %1: %2</source>
        <translation>Export nach %1 nicht möglich: %2</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exportieren</translation>
    </message>
    <message>
        <source>Export &amp;Zones…</source>
        <translation>Zo&amp;nen exportieren…</translation>
    </message>
    <message>
        <source>Export P&amp;lan (WGS84 GeoJSON, WKT)…</source>
        <translation>G&amp;rundriss exportieren (WGS84-GeoJSON, WKT)…</translation>
    </message>
    <message>
        <source>Importable plans (%1);;DXF drawings (*.dxf);;ROS occupancy maps (*.yaml *.yml);;WKT polygons (*.wkt);;GeoJSON plans (*.geojson *.json);;3D building models (*.ifc *.obj *.gltf *.glb *.stl)</source>
        <translation>Importierbare Pläne (%1);;DXF-Zeichnungen (*.dxf);;ROS-Belegungskarten (*.yaml *.yml);;WKT-Polygone (*.wkt);;GeoJSON-Pläne (*.geojson *.json);;3D-Gebäudemodelle (*.ifc *.obj *.gltf *.glb *.stl)</translation>
    </message>
    <message>
        <source>an untitled plan</source>
        <translation>einem unbenannten Plan</translation>
    </message>
    <message>
        <source>%1 (in %2)</source>
        <translation>%1 (in %2)</translation>
    </message>
    <message>
        <source>FloorCover did not close normally last time. Recover the unsaved changes to %1, saved automatically %2?</source>
        <translation>FloorCover wurde beim letzten Mal nicht normal beendet. Die ungesicherten Änderungen an %1 wiederherstellen (automatisch gesichert %2)?</translation>
    </message>
    <message>
        <source>Exported %1 to %2 (%3)</source>
        <translation>%1 nach %2 exportiert (%3)</translation>
    </message>
    <message>
        <source>Exported the path as %1 to
%2</source>
        <translation>Der Pfad wurde als %1 exportiert nach
%2</translation>
    </message>
    <message>
        <source>Exported the zones as %1 to
%2</source>
        <translation>Die Zonen wurden als %1 exportiert nach
%2</translation>
    </message>
    <message>
        <source>Exported the plan as %1 to
%2</source>
        <translation>Der Plan wurde als %1 exportiert nach
%2</translation>
    </message>
    <message>
        <source>Show in Folder</source>
        <translation>Im Ordner zeigen</translation>
    </message>
    <message>
        <source>&amp;Replan After Each Edit</source>
        <translation>Nach jeder Änderung &amp;neu planen</translation>
    </message>
    <message>
        <source>Plan the path again in the background whenever the floor, the rooms or the start and end change; the old path stays greyed until then.</source>
        <translation>Den Pfad im Hintergrund neu planen, sobald sich Grundriss, Räume, Start oder Ziel ändern; bis dahin bleibt der alte Pfad grau sichtbar.</translation>
    </message>
    <message>
        <source>Loaded the trained model %1</source>
        <translation>Trainiertes Modell %1 geladen</translation>
    </message>
    <message>
        <source>The trained model beside the project was not loaded (%1): %2</source>
        <translation>Das trainierte Modell neben dem Projekt wurde nicht geladen (%1): %2</translation>
    </message>
    <message>
        <source>The project was saved, but not its trained model: %1</source>
        <translation>Das Projekt wurde gespeichert, sein trainiertes Modell jedoch nicht: %1</translation>
    </message>
    <message>
        <source>&amp;Path View</source>
        <translation>P&amp;fadansicht</translation>
    </message>
    <message>
        <source>The floor, the rooms and the path with its start and end</source>
        <translation>Der Boden, die Räume und der Pfad mit Start und Ziel</translation>
    </message>
    <message>
        <source>&amp;Graph View</source>
        <translation>Gr&amp;aphansicht</translation>
    </message>
    <message>
        <source>Adds the planner&apos;s cells, corners and graph edges</source>
        <translation>Zeigt zusätzlich die Zellen, Ecken und Graphkanten des Planers</translation>
    </message>
    <message>
        <source>Open &amp;Sample</source>
        <translation>Beispie&amp;l öffnen</translation>
    </message>
    <message>
        <source>PDF report, A4 (*.pdf)</source>
        <translation>PDF-Bericht, A4 (*.pdf)</translation>
    </message>
    <message>
        <source>PDF report, A3 (*.pdf)</source>
        <translation>PDF-Bericht, A3 (*.pdf)</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>&amp;Getting Started</source>
        <translation>&amp;Erste Schritte</translation>
    </message>
    <message>
        <source>A short guide through a first plan</source>
        <translation>Eine kurze Anleitung durch einen ersten Plan</translation>
    </message>
    <message>
        <source>&amp;Welcome Page</source>
        <translation>&amp;Willkommensseite</translation>
    </message>
    <message>
        <source>The sample plans and the ways to start</source>
        <translation>Die Beispielpläne und die Wege zum Einstieg</translation>
    </message>
    <message>
        <source>Opened %1: %2</source>
        <translation>%1 geöffnet: %2</translation>
    </message>
</context>
<context>
    <name>fc::ui::OverlayLayer</name>
    <message>
        <source>Primary Cells</source>
        <translation>Primärzellen</translation>
    </message>
    <message>
        <source>Transition Cells</source>
        <translation>Übergangszellen</translation>
    </message>
    <message>
        <source>Critical Slices</source>
        <translation>Kritische Schnitte</translation>
    </message>
    <message>
        <source>Corner Nodes</source>
        <translation>Eckknoten</translation>
    </message>
    <message>
        <source>Coverage Edges</source>
        <translation>Abdeckungskanten</translation>
    </message>
    <message>
        <source>Contour Edges</source>
        <translation>Konturkanten</translation>
    </message>
    <message>
        <source>Inter-cell Edges</source>
        <translation>Zellübergangskanten</translation>
    </message>
    <message>
        <source>Path</source>
        <translation>Pfad</translation>
    </message>
    <message>
        <source>Overlap Segments</source>
        <translation>Überlappungen</translation>
    </message>
    <message>
        <source>Unreachable Areas</source>
        <translation>Unerreichbare Flächen</translation>
    </message>
    <message>
        <source>Unreachable: %1 (%2 m²)</source>
        <translation>Unerreichbar: %1 (%2 m²)</translation>
    </message>
    <message>
        <source>Coverage Gaps</source>
        <translation>Abdeckungslücken</translation>
    </message>
    <message>
        <source>The cells the floor is split into, one colour per room, with their numbers</source>
        <translation>Die Zellen, in die der Boden geteilt wird, eine Farbe je Raum, mit ihren Nummern</translation>
    </message>
    <message>
        <source>Narrow strips between cells the robot passes through (hatched)</source>
        <translation>Schmale Streifen zwischen Zellen, durch die der Roboter fährt (schraffiert)</translation>
    </message>
    <message>
        <source>Where the floor&apos;s shape changes and one cell ends (dashed)</source>
        <translation>Wo sich die Form des Bodens ändert und eine Zelle endet (gestrichelt)</translation>
    </message>
    <message>
        <source>The cells&apos; corners, where the path may enter or leave a cell</source>
        <translation>Die Ecken der Zellen, an denen der Pfad in eine Zelle hinein- oder aus ihr herausführen kann</translation>
    </message>
    <message>
        <source>Which corners a cell&apos;s stripes join (entry and exit pairs)</source>
        <translation>Welche Ecken die Bahnen einer Zelle verbinden (Paare aus Ein- und Ausgang)</translation>
    </message>
    <message>
        <source>Moves along a cell&apos;s edge between its corners</source>
        <translation>Fahrten entlang des Rands einer Zelle zwischen ihren Ecken</translation>
    </message>
    <message>
        <source>Moves from one cell to the next</source>
        <translation>Fahrten von einer Zelle zur nächsten</translation>
    </message>
    <message>
        <source>The robot&apos;s path: cleaning stripes in red, transit moves dashed, arrows for the direction</source>
        <translation>Der Pfad des Roboters: Reinigungsbahnen rot, Leerfahrten gestrichelt, Pfeile zeigen die Richtung</translation>
    </message>
    <message>
        <source>Where the path passes over floor it has already cleaned (blue)</source>
        <translation>Wo der Pfad über bereits gereinigten Boden fährt (blau)</translation>
    </message>
    <message>
        <source>Floor the robot cannot reach: gaps narrower than the robot, corners beyond its head</source>
        <translation>Boden, den der Roboter nicht erreicht: Durchgänge schmaler als der Roboter, Ecken außer Reichweite seines Reinigungskopfs</translation>
    </message>
    <message>
        <source>Spots the robot could clean but the path misses</source>
        <translation>Stellen, die der Roboter reinigen könnte, die der Pfad aber auslässt</translation>
    </message>
</context>
<context>
    <name>fc::ui::PathPreviewBar</name>
    <message>
        <source>Preview</source>
        <translation>Vorschau</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Abspielen</translation>
    </message>
    <message>
        <source>Drive the robot along the planned path.</source>
        <translation>Den Roboter den geplanten Pfad abfahren lassen.</translation>
    </message>
    <message>
        <source>Speed-up over the robot&apos;s real speed.</source>
        <translation>Beschleunigung gegenüber der echten Geschwindigkeit des Roboters.</translation>
    </message>
    <message>
        <source>Position along the path.</source>
        <translation>Position entlang des Pfads.</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>×%1</source>
        <translation>×%1</translation>
    </message>
</context>
<context>
    <name>fc::ui::PdfReport</name>
    <message>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <source>&lt; 1 min</source>
        <translation>&lt; 1 min</translation>
    </message>
    <message>
        <source>%1 min</source>
        <translation>%1 min</translation>
    </message>
    <message>
        <source>%1 h %2 min</source>
        <translation>%1 h %2 min</translation>
    </message>
    <message>
        <source>(%1, %2) m</source>
        <translation>(%1; %2) m</translation>
    </message>
    <message>
        <source>per room, along its walls</source>
        <translation>je Raum, entlang seiner Wände</translation>
    </message>
    <message>
        <source>%1°</source>
        <translation>%1°</translation>
    </message>
    <message>
        <source>Rooms planned</source>
        <translation>Geplante Räume</translation>
    </message>
    <message>
        <source>%1 of %2</source>
        <translation>%1 von %2</translation>
    </message>
    <message>
        <source>Estimated time</source>
        <translation>Geschätzte Dauer</translation>
    </message>
    <message>
        <source>Path length</source>
        <translation>Pfadlänge</translation>
    </message>
    <message>
        <source>Extra distance</source>
        <translation>Zusätzliche Strecke</translation>
    </message>
    <message>
        <source>%1 (%2 % over the ideal %3)</source>
        <translation>%1 (%2 % über dem Idealwert %3)</translation>
    </message>
    <message>
        <source>Turns</source>
        <translation>Wendungen</translation>
    </message>
    <message>
        <source>Coverage</source>
        <translation>Abdeckung</translation>
    </message>
    <message>
        <source>%1 % of the floor the robot can reach</source>
        <translation>%1 % des für den Roboter erreichbaren Bodens</translation>
    </message>
    <message>
        <source>Missed</source>
        <translation>Nicht abgedeckt</translation>
    </message>
    <message>
        <source>%1 m²</source>
        <translation>%1 m²</translation>
    </message>
    <message>
        <source>Too narrow for the robot</source>
        <translation>Zu eng für den Roboter</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Starten</translation>
    </message>
    <message>
        <source>%1, chosen by the planner</source>
        <translation>%1, vom Planer gewählt</translation>
    </message>
    <message>
        <source>End</source>
        <translation>Ziel</translation>
    </message>
    <message>
        <source>Planner</source>
        <translation>Planer</translation>
    </message>
    <message>
        <source>%1, stripes %2</source>
        <translation>%1, Bahnen %2</translation>
    </message>
    <message>
        <source>Robot diameter L</source>
        <translation>Roboterdurchmesser L</translation>
    </message>
    <message>
        <source>Cleaning diameter D</source>
        <translation>Reinigungsdurchmesser D</translation>
    </message>
    <message>
        <source>Coverage width W</source>
        <translation>Bahnbreite W</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <source>%1 m/s</source>
        <translation>%1 m/s</translation>
    </message>
    <message>
        <source>Time per 90° turn</source>
        <translation>Zeit je 90°-Drehung</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>Order</source>
        <translation>Reihenfolge</translation>
    </message>
    <message>
        <source>Room</source>
        <translation>Raum</translation>
    </message>
    <message>
        <source>Area</source>
        <translation>Fläche</translation>
    </message>
    <message>
        <source>Path</source>
        <translation>Pfad</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <source>not planned</source>
        <translation>nicht geplant</translation>
    </message>
    <message>
        <source>Between rooms</source>
        <translation>Zwischen Räumen</translation>
    </message>
    <message>
        <source>Total</source>
        <translation>Gesamt</translation>
    </message>
    <message>
        <source>S</source>
        <translation>S</translation>
    </message>
    <message>
        <source>E</source>
        <translation>Z</translation>
    </message>
    <message>
        <source>Cleaning path</source>
        <translation>Reinigungspfad</translation>
    </message>
    <message>
        <source>Transit</source>
        <translation>Leerfahrt</translation>
    </message>
    <message>
        <source>Overlap</source>
        <translation>Überlappung</translation>
    </message>
    <message>
        <source>Missed spots</source>
        <translation>Ausgelassene Stellen</translation>
    </message>
    <message>
        <source>Too narrow</source>
        <translation>Zu eng</translation>
    </message>
    <message>
        <source>Rooms in cleaning order</source>
        <translation>Räume in Reinigungsreihenfolge</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source>Cleaning plan: %1</source>
        <translation>Reinigungsplan: %1</translation>
    </message>
    <message>
        <source>Cannot write %1.</source>
        <translation>%1 kann nicht geschrieben werden.</translation>
    </message>
    <message>
        <source>Summary</source>
        <translation>Zusammenfassung</translation>
    </message>
    <message>
        <source>Robot profile</source>
        <translation>Roboterprofil</translation>
    </message>
</context>
<context>
    <name>fc::ui::PickRoomTool</name>
    <message>
        <source>Pick Rooms</source>
        <translation>Räume wählen</translation>
    </message>
    <message>
        <source>Pick Rooms: click a room to include it in or exclude it from planning.</source>
        <translation>Räume wählen: einen Raum anklicken, um ihn in die Planung aufzunehmen oder auszuschließen.</translation>
    </message>
    <message>
        <source>No room here.</source>
        <translation>Hier ist kein Raum.</translation>
    </message>
</context>
<context>
    <name>fc::ui::PlaceEndpointTool</name>
    <message>
        <source>Place Start</source>
        <translation>Start setzen</translation>
    </message>
    <message>
        <source>Place End</source>
        <translation>Ziel setzen</translation>
    </message>
    <message>
        <source>Place End: click where the robot should finish; right-click removes it (the path then returns to the start).</source>
        <translation>Ziel setzen: dort klicken, wo der Roboter enden soll; Rechtsklick entfernt es (der Pfad kehrt dann zum Start zurück).</translation>
    </message>
    <message>
        <source>S</source>
        <translation>S</translation>
    </message>
    <message>
        <source>E</source>
        <translation>Z</translation>
    </message>
    <message>
        <source>%1: the point must lie inside the floor.</source>
        <translation>%1: Der Punkt muss innerhalb der Fläche liegen.</translation>
    </message>
    <message>
        <source>Place Start: click where the robot starts (moved off a wall to where the robot fits); right-click removes it.</source>
        <translation>Start setzen: klicken Sie, wo der Roboter beginnt (von einer Wand weg dorthin gerückt, wo der Roboter passt); Rechtsklick entfernt ihn.</translation>
    </message>
    <message>
        <source>%1: that point is inside an obstacle; click on the floor.</source>
        <translation>%1: dieser Punkt liegt in einem Hindernis; klicken Sie auf den Boden.</translation>
    </message>
    <message>
        <source>%1: the robot (%2 m across) does not fit there or nearby.</source>
        <translation>%1: der Roboter (%2 m breit) passt dort und in der Nähe nicht hin.</translation>
    </message>
    <message>
        <source>%1: moved %2 m off the wall, where the robot fits.</source>
        <translation>%1: um %2 m von der Wand weg gerückt, wo der Roboter passt.</translation>
    </message>
</context>
<context>
    <name>fc::ui::PlanScene</name>
    <message>
        <source>%1 (planned)</source>
        <translation>%1 (geplant)</translation>
    </message>
    <message>
        <source>%1 (not planned)</source>
        <translation>%1 (nicht geplant)</translation>
    </message>
    <message>
        <source>S</source>
        <translation>S</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>E</source>
        <translation>Z</translation>
    </message>
    <message>
        <source>End</source>
        <translation>Ziel</translation>
    </message>
    <message>
        <source>The corner the planner starts or ends at</source>
        <translation>Die Ecke, an der der Planer beginnt oder endet</translation>
    </message>
    <message>
        <source>Start, chosen by the planner</source>
        <translation>Start, vom Planer gewählt</translation>
    </message>
    <message>
        <source>End of the path</source>
        <translation>Ende des Pfads</translation>
    </message>
</context>
<context>
    <name>fc::ui::PlanningController</name>
    <message>
        <source>Preparing the overlays</source>
        <translation>Überlagerungen werden vorbereitet</translation>
    </message>
    <message>
        <source>Planning the path</source>
        <translation>Pfad wird geplant</translation>
    </message>
    <message>
        <source>Sketching the path</source>
        <translation>Pfad wird skizziert</translation>
    </message>
    <message>
        <source>This plan has problems: repair it first (Plan &gt; Repair Plan, or the button in the Problems panel).</source>
        <translation>Dieser Plan hat Probleme: Reparieren Sie ihn zuerst (Planen &gt; Plan reparieren oder die Schaltfläche im Bereich Probleme).</translation>
    </message>
</context>
<context>
    <name>fc::ui::PlanningDock</name>
    <message>
        <source>Planning</source>
        <translation>Planung</translation>
    </message>
    <message>
        <source>Rooms to plan</source>
        <translation>Zu planende Räume</translation>
    </message>
    <message>
        <source>Plan</source>
        <translation>Planen</translation>
    </message>
    <message>
        <source>Plan the coverage path for the checked rooms (F5).</source>
        <translation>Den Abdeckungspfad für die angekreuzten Räume planen (F5).</translation>
    </message>
    <message>
        <source>Robot</source>
        <translation>Roboter</translation>
    </message>
    <message>
        <source> m</source>
        <translation> m</translation>
    </message>
    <message>
        <source> m/s</source>
        <translation> m/s</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Robot diameter L</source>
        <translation>Roboterdurchmesser L</translation>
    </message>
    <message>
        <source>Cleaning diameter D</source>
        <translation>Reinigungsdurchmesser D</translation>
    </message>
    <message>
        <source>Coverage width W</source>
        <translation>Bahnbreite W</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <source>Time per 90° turn</source>
        <translation>Zeit je 90°-Drehung</translation>
    </message>
    <message>
        <source>Sweep</source>
        <translation>Bahnen</translation>
    </message>
    <message>
        <source>°</source>
        <translation>°</translation>
    </message>
    <message>
        <source>Stripe angle</source>
        <translation>Bahnwinkel</translation>
    </message>
    <message>
        <source>Solver</source>
        <translation>Löser</translation>
    </message>
    <message>
        <source>Metrics</source>
        <translation>Kennzahlen</translation>
    </message>
    <message>
        <source>Length</source>
        <translation>Länge</translation>
    </message>
    <message>
        <source>Extra distance</source>
        <translation>Zusätzliche Strecke</translation>
    </message>
    <message>
        <source>Turns</source>
        <translation>Wendungen</translation>
    </message>
    <message>
        <source>Coverage</source>
        <translation>Abdeckung</translation>
    </message>
    <message>
        <source>Estimated time</source>
        <translation>Geschätzte Dauer</translation>
    </message>
    <message>
        <source>Cells</source>
        <translation>Zellen</translation>
    </message>
    <message>
        <source>Planning time</source>
        <translation>Planungszeit</translation>
    </message>
    <message>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>%1 min %2 s</source>
        <translation>%1 min %2 s</translation>
    </message>
    <message>
        <source>%1°</source>
        <translation>%1°</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>Planning…</source>
        <translation>Planung läuft…</translation>
    </message>
    <message>
        <source>Draw the boundary of the floor to see cells and plan a path.</source>
        <translation>Zeichnen Sie die Außenwand der Fläche, um Zellen zu sehen und einen Pfad zu planen.</translation>
    </message>
    <message>
        <source>Per room, along its walls</source>
        <translation>Je Raum, entlang seiner Wände</translation>
    </message>
    <message>
        <source>Auto: fastest full coverage</source>
        <translation>Automatisch: schnellste volle Abdeckung</translation>
    </message>
    <message>
        <source>One angle for the floor</source>
        <translation>Ein Winkel für die ganze Etage</translation>
    </message>
    <message>
        <source>Per room: each room&apos;s stripes follow its own walls (set a room&apos;s angle below to override it). Auto: tries several angles for the whole floor and keeps the fastest plan that covers everything the robot can reach. One angle: the stripe angle below for every room.</source>
        <translation>Je Raum: die Bahnen jedes Raums folgen seinen eigenen Wänden (unten lässt sich der Winkel eines Raums festlegen). Automatisch: probiert mehrere Winkel für die ganze Etage und behält den schnellsten Plan, der alles abdeckt, was der Roboter erreichen kann. Ein Winkel: der Bahnwinkel unten für jeden Raum.</translation>
    </message>
    <message>
        <source>Room</source>
        <translation>Raum</translation>
    </message>
    <message>
        <source>From walls</source>
        <translation>Aus den Wänden</translation>
    </message>
    <message>
        <source>Fixed</source>
        <translation>Festgelegt</translation>
    </message>
    <message>
        <source>Uncovered</source>
        <translation>Nicht abgedeckt</translation>
    </message>
    <message>
        <source>Unreachable</source>
        <translation>Unerreichbar</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not an angle in degrees.</source>
        <translation>„%1“ ist kein Winkel in Grad.</translation>
    </message>
    <message>
        <source>%1 m² (%2 %)</source>
        <translation>%1 m² (%2 %)</translation>
    </message>
    <message>
        <source>Check the rooms to cover; double-click a name to rename the room. Select two rooms (Ctrl+click) to merge them; split a room with the Split Room tool (K).</source>
        <translation>Kreuzen Sie die abzudeckenden Räume an; Doppelklick auf einen Namen benennt den Raum um. Zwei Räume auswählen (Strg+Klick), um sie zusammenzuführen; einen Raum mit dem Werkzeug „Raum teilen“ (K) teilen.</translation>
    </message>
    <message>
        <source>Merge Selected Rooms</source>
        <translation>Ausgewählte Räume zusammenführen</translation>
    </message>
    <message>
        <source>Join the two selected rooms into one (they must share a wall or a doorway); the first keeps its name.</source>
        <translation>Die zwei ausgewählten Räume zu einem verbinden (sie müssen eine Wand oder eine Tür teilen); der erste behält seinen Namen.</translation>
    </message>
    <message>
        <source>A quick sketch of the path is shown; the planner is refining it…</source>
        <translation>Eine schnelle Skizze des Pfads wird angezeigt; der Planer verfeinert sie…</translation>
    </message>
    <message>
        <source>The robot&apos;s body, L: its centre keeps L/2 from walls, and doors narrower than L are not passed.</source>
        <translation>Der Körper des Roboters, L: Seine Mitte hält L/2 Abstand zu Wänden, und durch Türen schmaler als L fährt er nicht.</translation>
    </message>
    <message>
        <source>The width the cleaning head reaches, D (at least W).</source>
        <translation>Die Breite, die der Reinigungskopf erreicht, D (mindestens W).</translation>
    </message>
    <message>
        <source>Distance between neighbouring stripes, W (between L and D): smaller overlaps more, larger risks gaps.</source>
        <translation>Abstand zwischen benachbarten Bahnen, W (zwischen L und D): kleiner überlappt mehr, größer riskiert Lücken.</translation>
    </message>
    <message>
        <source>Driving speed, for the estimated time.</source>
        <translation>Fahrgeschwindigkeit, für die geschätzte Dauer.</translation>
    </message>
    <message>
        <source>Seconds the robot needs to turn by 90°, for the estimated time.</source>
        <translation>Sekunden, die der Roboter für eine 90°-Drehung braucht, für die geschätzte Dauer.</translation>
    </message>
    <message>
        <source>The stripes&apos; direction in degrees (90 = vertical), for One angle for the floor.</source>
        <translation>Die Richtung der Bahnen in Grad (90 = senkrecht), für „Ein Winkel für die ganze Etage“.</translation>
    </message>
    <message>
        <source>How the order of the cells is chosen: heuristic is fast and close to the best; exact proves the best order on small floors; greedy is the quickest sketch; dqn uses the model trained in the Training panel, or the built-in generalist model when none is; dqn-search lets that model guide a search for 2 seconds per part of the floor (better than heuristic on large floors).</source>
        <translation>Wie die Reihenfolge der Zellen gewählt wird: heuristic ist schnell und nahe am Besten; exact beweist die beste Reihenfolge auf kleinen Flächen; greedy ist die schnellste Skizze; dqn nutzt das im Bereich Training trainierte Modell oder, wenn keines trainiert ist, das eingebaute allgemeine Modell; dqn-search lässt dieses Modell 2 Sekunden je Teil der Fläche eine Suche leiten (auf großen Flächen besser als heuristic).</translation>
    </message>
    <message>
        <source>Planned</source>
        <translation>Geplant</translation>
    </message>
    <message>
        <source>Type an angle in degrees to fix a room&apos;s stripes; clear it to follow the room&apos;s walls again. Planned: the angle the last plan swept the room at (the planner may turn a room by 90° or along its other walls where that plans faster).</source>
        <translation>Einen Winkel in Grad eingeben, um die Bahnen eines Raums festzulegen; leeren, um wieder den Wänden des Raums zu folgen. Geplant: der Winkel, in dem der letzte Plan den Raum gefahren ist (der Planer kann einen Raum um 90° drehen oder an seinen anderen Wänden ausrichten, wo das schneller ist).</translation>
    </message>
    <message numerus="yes">
        <source>Wall teeth cut back to their walls for planning: %n (pilasters, bumps of traced walls); the path keeps clear of them.</source>
        <translation>
            <numerusform>Für die Planung auf die Wandlinie zurückgenommene Wandvorsprünge: %n (Pilaster, Höcker gescannter Wände); der Pfad hält Abstand davon.</numerusform>
            <numerusform>Für die Planung auf die Wandlinie zurückgenommene Wandvorsprünge: %n (Pilaster, Höcker gescannter Wände); der Pfad hält Abstand davon.</numerusform>
        </translation>
    </message>
    <message>
        <source>Planned as loops along the walls, each one coverage width further in: estimated faster than stripes on this floor.</source>
        <translation>Als Runden entlang der Wände geplant, jede eine Reinigungsbreite weiter innen: auf dieser Fläche schneller geschätzt als Bahnen.</translation>
    </message>
</context>
<context>
    <name>fc::ui::PpoTrainer</name>
    <message>
        <source>Training ppo</source>
        <translation>PPO-Training</translation>
    </message>
</context>
<context>
    <name>fc::ui::PpoTrainingPanel</name>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Training time for the ppo policy (it learns on random rooms, so one model serves every floor)</source>
        <translation>Trainingszeit der ppo-Strategie (sie lernt auf zufälligen Räumen, ein Modell dient also jedem Grundriss)</translation>
    </message>
    <message>
        <source>Train ppo</source>
        <translation>ppo trainieren</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Anhalten</translation>
    </message>
    <message>
        <source>ppo trains on first use (about a minute); train it here to watch it learn.</source>
        <translation>ppo trainiert bei der ersten Verwendung (etwa eine Minute); hier trainiert, sehen Sie ihm beim Lernen zu.</translation>
    </message>
    <message>
        <source>PPO update</source>
        <translation>PPO-Aktualisierung</translation>
    </message>
    <message>
        <source>Energy per waypoint (kg m)</source>
        <translation>Energie je Wegpunkt (kg m)</translation>
    </message>
    <message>
        <source>Trained for %1 updates; ppo now plans with %2.</source>
        <translation>%1 Aktualisierungen trainiert; ppo plant jetzt mit %2.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Training failed:&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;Training fehlgeschlagen:&lt;/b&gt; %1</translation>
    </message>
    <message>
        <source>Training…</source>
        <translation>Training läuft…</translation>
    </message>
    <message>
        <source>Update %1, %2 kg m per waypoint, %3 s</source>
        <translation>Aktualisierung %1, %2 kg m je Wegpunkt, %3 s</translation>
    </message>
    <message>
        <source>Training cancelled before its first update; no model.</source>
        <translation>Training vor der ersten Aktualisierung abgebrochen; kein Modell.</translation>
    </message>
    <message>
        <source>Train the learnt ordering (ppo) in the background for the time set.</source>
        <translation>Die gelernte Reihenfolge (ppo) für die eingestellte Zeit im Hintergrund trainieren.</translation>
    </message>
    <message>
        <source>End training; what was learnt so far is kept.</source>
        <translation>Training beenden; das bisher Gelernte bleibt erhalten.</translation>
    </message>
</context>
<context>
    <name>fc::ui::PreferencesDialog</name>
    <message>
        <source>Preferences</source>
        <translation>Einstellungen</translation>
    </message>
    <message>
        <source>The language changes at the next start of FloorCover.</source>
        <translation>Die Sprache wechselt beim nächsten Start von FloorCover.</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Sprache</translation>
    </message>
    <message>
        <source>The language of the editor, its messages and Qt&apos;s dialogs</source>
        <translation>Die Sprache des Editors, seiner Meldungen und der Qt-Dialoge</translation>
    </message>
</context>
<context>
    <name>fc::ui::ProblemsDock</name>
    <message>
        <source>Problems</source>
        <translation>Probleme</translation>
    </message>
    <message>
        <source>Repair Plan</source>
        <translation>Plan reparieren</translation>
    </message>
    <message>
        <source>&amp;Repair Plan</source>
        <translation>Plan &amp;reparieren</translation>
    </message>
    <message>
        <source>Click a problem to see where it is on the plan.</source>
        <translation>Klicken Sie auf ein Problem, um zu sehen, wo es im Plan liegt.</translation>
    </message>
    <message>
        <source>Makes the plan valid: walls that cross themselves are split where they cross, obstacles that overlap or cross the wall are merged or clipped, rooms are fitted to the floor. Undo (Ctrl+Z) brings the plan back as it was.</source>
        <translation>Macht den Plan gültig: Wände, die sich selbst kreuzen, werden an der Kreuzung geteilt; Hindernisse, die sich überlappen oder die Wand kreuzen, werden zusammengeführt oder beschnitten; Räume werden an den Boden angepasst. Rückgängig (Strg+Z) stellt den Plan wieder her, wie er war.</translation>
    </message>
    <message numerus="yes">
        <source>This plan cannot be planned as it is: %n problem(s). It is open read-only and nothing is lost; repair it to plan.</source>
        <translation>
            <numerusform>Dieser Plan lässt sich so nicht planen: %n Problem. Er ist schreibgeschützt geöffnet, und nichts geht verloren; reparieren Sie ihn, um zu planen.</numerusform>
            <numerusform>Dieser Plan lässt sich so nicht planen: %n Probleme. Er ist schreibgeschützt geöffnet, und nichts geht verloren; reparieren Sie ihn, um zu planen.</numerusform>
        </translation>
    </message>
    <message>
        <source>Repaired. What changed (Edit &gt; Undo brings the old plan back):</source>
        <translation>Repariert. Was sich geändert hat (Bearbeiten &gt; Rückgängig holt den alten Plan zurück):</translation>
    </message>
    <message>
        <source>No problems: the plan can be planned.</source>
        <translation>Keine Probleme: Der Plan kann geplant werden.</translation>
    </message>
</context>
<context>
    <name>fc::ui::SiteBuildingChoice</name>
    <message>
        <source>Building %1 (%2 m²)</source>
        <translation>Gebäude %1 (%2 m²)</translation>
    </message>
    <message>
        <source>Choose a Building</source>
        <translation>Gebäude wählen</translation>
    </message>
    <message>
        <source>%1 holds %2 buildings, and a plan holds one.
Which building do you want to open?</source>
        <translation>%1 enthält %2 Gebäude, ein Plan aber nur eines.
Welches Gebäude möchten Sie öffnen?</translation>
    </message>
</context>
<context>
    <name>fc::ui::SplitRoomTool</name>
    <message>
        <source>Split Room</source>
        <translation>Raum teilen</translation>
    </message>
    <message>
        <source>Split Room: drag a line across a room to cut it in two (Esc cancels); the larger part keeps the name.</source>
        <translation>Raum teilen: eine Linie quer über einen Raum ziehen, um ihn zu teilen (Esc bricht ab); der größere Teil behält den Namen.</translation>
    </message>
    <message>
        <source>Split Room: drag the cut across the room.</source>
        <translation>Raum teilen: den Schnitt quer über den Raum ziehen.</translation>
    </message>
    <message>
        <source>Split Room: the cut must cross a room.</source>
        <translation>Raum teilen: der Schnitt muss einen Raum kreuzen.</translation>
    </message>
    <message>
        <source>Split %1 in two.</source>
        <translation>%1 in zwei geteilt.</translation>
    </message>
</context>
<context>
    <name>fc::ui::TaskListWidget</name>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Cancel: %1</source>
        <translation>Abbrechen: %1</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1 (cancelling…)</source>
        <translation>%1 (wird abgebrochen…)</translation>
    </message>
</context>
<context>
    <name>fc::ui::TilingController</name>
    <message>
        <source>Tiling with %1</source>
        <translation>Kachelung mit %1</translation>
    </message>
</context>
<context>
    <name>fc::ui::TilingDock</name>
    <message>
        <source>Tiling Robot</source>
        <translation>Kachelroboter</translation>
    </message>
    <message>
        <source>How the tiles are ordered: zigzag and spiral follow the rows, greedy, aco and ga minimise the energy, exact only for a few tiles, ppo is the learnt pointer network.</source>
        <translation>Wie die Kacheln geordnet werden: zigzag und spiral folgen den Reihen, greedy, aco und ga minimieren die Energie, exact nur für wenige Kacheln, ppo ist das gelernte Pointer-Netz.</translation>
    </message>
    <message>
        <source>Ordering:</source>
        <translation>Reihenfolge:</translation>
    </message>
    <message>
        <source>Seed:</source>
        <translation>Startwert:</translation>
    </message>
    <message>
        <source> m</source>
        <translation> m</translation>
    </message>
    <message>
        <source>Block leg:</source>
        <translation>Blockkathete:</translation>
    </message>
    <message>
        <source>Mass of block B%1 in kg</source>
        <translation>Masse von Block B%1 in kg</translation>
    </message>
    <message>
        <source>Block masses (kg):</source>
        <translation>Blockmassen (kg):</translation>
    </message>
    <message>
        <source>Tile and Order</source>
        <translation>Kacheln und ordnen</translation>
    </message>
    <message>
        <source>Show tiles on the canvas</source>
        <translation>Kacheln auf der Zeichenfläche zeigen</translation>
    </message>
    <message>
        <source>Export Waypoints…</source>
        <translation>Wegpunkte exportieren…</translation>
    </message>
    <message>
        <source>Learnt ordering (ppo)</source>
        <translation>Gelernte Reihenfolge (ppo)</translation>
    </message>
    <message>
        <source>Tiling and ordering… (ppo trains its network first)</source>
        <translation>Kacheln und ordnen… (ppo trainiert zuerst sein Netz)</translation>
    </message>
    <message>
        <source>Tiling and ordering…</source>
        <translation>Kacheln und ordnen…</translation>
    </message>
    <message>
        <source>&lt;b&gt;Cannot tile:&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;Kacheln nicht möglich:&lt;/b&gt; %1</translation>
    </message>
    <message>
        <source>Press “Tile and Order” to cover the floor with the robot&apos;s shapes and order the tiles by energy.</source>
        <translation>„Kacheln und ordnen“ drücken, um die Fläche mit den Formen des Roboters zu belegen und die Kacheln nach Energie zu ordnen.</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;: energy %2 kg m (translation %3, shape changes %4, turns %5)&lt;br&gt;%6 waypoints, %7 m, %8 shape changes, ordered in %9 s&lt;br&gt;%10 cells free, %11 left untiled, %12 unreachable (red)&lt;br&gt;%13</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;: Energie %2 kg m (Verschiebung %3, Formwechsel %4, Drehungen %5)&lt;br&gt;%6 Wegpunkte, %7 m, %8 Formwechsel, geordnet in %9 s&lt;br&gt;%10 Zellen frei, %11 ungekachelt, %12 unerreichbar (rot)&lt;br&gt;%13</translation>
    </message>
    <message>
        <source>No tiling to export: press “Tile and Order” first.</source>
        <translation>Keine Kachelung zum Exportieren: zuerst „Kacheln und ordnen“ drücken.</translation>
    </message>
    <message>
        <source>Export Waypoints</source>
        <translation>Wegpunkte exportieren</translation>
    </message>
    <message>
        <source>CSV (*.csv);;JSON (*.json)</source>
        <translation>CSV (*.csv);;JSON (*.json)</translation>
    </message>
    <message>
        <source>&lt;b&gt;Export failed:&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;Export fehlgeschlagen:&lt;/b&gt; %1</translation>
    </message>
    <message>
        <source>Random seed of the ordering methods that use chance (aco, ga, ppo): the same seed gives the same tour.</source>
        <translation>Startwert für die Verfahren, die mit Zufall arbeiten (aco, ga, ppo): Derselbe Startwert ergibt dieselbe Route.</translation>
    </message>
    <message>
        <source>Side of one block of the tiling robot in metres.</source>
        <translation>Seitenlänge eines Blocks des Kachelroboters in Metern.</translation>
    </message>
    <message>
        <source>Tile the floor with the robot&apos;s shapes and order the tiles by energy.</source>
        <translation>Die Fläche mit den Formen des Roboters kacheln und die Kacheln nach Energie ordnen.</translation>
    </message>
    <message>
        <source>Draw the tiles and their tour over the plan.</source>
        <translation>Die Kacheln und ihre Route über dem Plan zeichnen.</translation>
    </message>
    <message>
        <source>Write the ordered waypoints (position, shape, heading) as CSV or JSON for the robot.</source>
        <translation>Die geordneten Wegpunkte (Position, Form, Ausrichtung) als CSV oder JSON für den Roboter schreiben.</translation>
    </message>
</context>
<context>
    <name>fc::ui::TilingMode</name>
    <message>
        <source>&amp;Tiling Robot Mode</source>
        <translation>&amp;Kachelroboter-Modus</translation>
    </message>
    <message>
        <source>Cover the floor with a shape-shifting tiling robot&apos;s tiles and order them by energy</source>
        <translation>Die Fläche mit den Kacheln eines formwandelnden Kachelroboters belegen und sie nach Energie ordnen</translation>
    </message>
</context>
<context>
    <name>fc::ui::TrainingDock</name>
    <message>
        <source>Training</source>
        <translation>Training</translation>
    </message>
    <message>
        <source>Improved</source>
        <translation>Verbessert</translation>
    </message>
    <message>
        <source>Paper</source>
        <translation>Wie im Artikel</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Training time for one run</source>
        <translation>Trainingszeit für einen Lauf</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Starten</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <source>No model yet</source>
        <translation>Noch kein Modell</translation>
    </message>
    <message>
        <source>Episode</source>
        <translation>Episode</translation>
    </message>
    <message>
        <source>Reward</source>
        <translation>Belohnung</translation>
    </message>
    <message>
        <source>Loss / epsilon</source>
        <translation>Verlust / Epsilon</translation>
    </message>
    <message>
        <source>Episode reward</source>
        <translation>Episodenbelohnung</translation>
    </message>
    <message>
        <source>Moving average (100)</source>
        <translation>Gleitender Mittelwert (100)</translation>
    </message>
    <message>
        <source>Loss</source>
        <translation>Verlust</translation>
    </message>
    <message>
        <source>Epsilon</source>
        <translation>Epsilon</translation>
    </message>
    <message>
        <source>Save Model…</source>
        <translation>Modell speichern…</translation>
    </message>
    <message>
        <source>Load Model…</source>
        <translation>Modell laden…</translation>
    </message>
    <message>
        <source>The plan changed: the model no longer fits it. Start to train for the new plan.</source>
        <translation>Der Plan hat sich geändert: Das Modell passt nicht mehr dazu. Starten Sie das Training für den neuen Plan.</translation>
    </message>
    <message>
        <source>There is no valid plan to train for.</source>
        <translation>Es gibt keinen gültigen Plan zum Trainieren.</translation>
    </message>
    <message>
        <source>Episode %1 · %2 steps/s · epsilon %3 · average reward %4</source>
        <translation>Episode %1 · %2 Schritte/s · Epsilon %3 · mittlere Belohnung %4</translation>
    </message>
    <message>
        <source>%1% · %2 left</source>
        <translation>%1 % · noch %2</translation>
    </message>
    <message>
        <source>Model after %1 episodes (%2 of training) ready for solver dqn</source>
        <translation>Modell nach %1 Episoden (%2 Training) für den Löser dqn bereit</translation>
    </message>
    <message>
        <source>Pause the training before saving the model.</source>
        <translation>Pausieren Sie das Training, bevor Sie das Modell speichern.</translation>
    </message>
    <message>
        <source>Cannot save the model to %1: %2</source>
        <translation>Das Modell kann nicht nach %1 gespeichert werden: %2</translation>
    </message>
    <message>
        <source>Stop the training before loading a model.</source>
        <translation>Stoppen Sie das Training, bevor Sie ein Modell laden.</translation>
    </message>
    <message>
        <source>Loaded %1 (%2 episodes of training)</source>
        <translation>%1 geladen (%2 Episoden Training)</translation>
    </message>
    <message>
        <source>Save Model</source>
        <translation>Modell speichern</translation>
    </message>
    <message>
        <source>FloorCover DQN model (*.fcdqn)</source>
        <translation>FloorCover-DQN-Modell (*.fcdqn)</translation>
    </message>
    <message>
        <source>Load Model</source>
        <translation>Modell laden</translation>
    </message>
    <message>
        <source>%p%</source>
        <translation>%p %</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Fortsetzen</translation>
    </message>
    <message>
        <source>Graph state</source>
        <translation>Graphzustand</translation>
    </message>
    <message>
        <source>Improved: masking, graph-cost reward, cost channels and a refined walk. Graph state: the same with per-corner features and a per-corner network (faster on large floors). Paper: the published setting.</source>
        <translation>Verbessert: Maskierung, Belohnung aus Graphkosten, Kostenkanäle und ein verfeinerter Weg. Graphzustand: dasselbe mit Merkmalen je Ecke und einem Netz je Ecke (schneller auf großen Grundrissen). Artikel: die veröffentlichte Einstellung.</translation>
    </message>
    <message>
        <source>Evaluate</source>
        <translation>Bewerten</translation>
    </message>
    <message>
        <source>Plan the model&apos;s test queries with it and compare with the exact or heuristic solver</source>
        <translation>Die Testanfragen des Modells damit planen und mit dem exakten oder heuristischen Löser vergleichen</translation>
    </message>
    <message>
        <source>Evaluating the model on its test queries…</source>
        <translation>Das Modell wird an seinen Testanfragen bewertet…</translation>
    </message>
    <message>
        <source>On %1 test queries: the policy alone is %2% above the %3 solver; solver dqn is %4% above it, %5 ms per query.</source>
        <translation>Bei %1 Testanfragen: Die Strategie allein liegt %2 % über dem Löser %3; der Löser dqn %4 % darüber, %5 ms pro Anfrage.</translation>
    </message>
    <message numerus="yes">
        <source>%n queries did not finish.</source>
        <translation>
            <numerusform>%n Anfrage wurde nicht beendet.</numerusform>
            <numerusform>%n Anfragen wurden nicht beendet.</numerusform>
        </translation>
    </message>
    <message>
        <source>Evaluation cancelled.</source>
        <translation>Bewertung abgebrochen.</translation>
    </message>
    <message>
        <source>Evaluation failed: %1</source>
        <translation>Bewertung fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>Training the DQN</source>
        <translation>DQN wird trainiert</translation>
    </message>
    <message>
        <source>there is no trained model yet</source>
        <translation>es gibt noch kein trainiertes Modell</translation>
    </message>
    <message>
        <source>Evaluating the DQN model</source>
        <translation>DQN-Modell wird bewertet</translation>
    </message>
    <message>
        <source>Training failed: %1</source>
        <translation>Training fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>Training cannot start: %1</source>
        <translation>Training kann nicht starten: %1</translation>
    </message>
    <message>
        <source>Done · %1 trained</source>
        <translation>Fertig · %1 trainiert</translation>
    </message>
    <message>
        <source>Paused at %p% · %1 trained</source>
        <translation>Angehalten bei %p% · %1 trainiert</translation>
    </message>
    <message>
        <source>cannot replace the file</source>
        <translation>die Datei kann nicht ersetzt werden</translation>
    </message>
    <message>
        <source>Train the learnt planner (solver dqn) for this plan in the background; the curve shows its reward per episode.</source>
        <translation>Den gelernten Planer (Löser dqn) für diesen Plan im Hintergrund trainieren; die Kurve zeigt seine Belohnung je Episode.</translation>
    </message>
    <message>
        <source>Pause training and keep the model so far; Resume goes on.</source>
        <translation>Training pausieren und das bisherige Modell behalten; Fortsetzen macht weiter.</translation>
    </message>
    <message>
        <source>End training; the model so far is kept for solver dqn.</source>
        <translation>Training beenden; das bisherige Modell bleibt für den Löser dqn erhalten.</translation>
    </message>
    <message>
        <source>Save the trained model to a .fcdqn file (saving the project also saves it beside the project).</source>
        <translation>Das trainierte Modell in einer .fcdqn-Datei speichern (beim Speichern des Projekts wird es auch neben dem Projekt gespeichert).</translation>
    </message>
    <message>
        <source>Load a model trained for this plan from a .fcdqn file.</source>
        <translation>Ein für diesen Plan trainiertes Modell aus einer .fcdqn-Datei laden.</translation>
    </message>
    <message>
        <source>there is no valid plan to load the model for</source>
        <translation>es gibt keinen gültigen Plan, für den das Modell geladen werden könnte</translation>
    </message>
    <message>
        <source>Policy gap (%)</source>
        <translation>Abstand der Strategie (%)</translation>
    </message>
    <message>
        <source>Policy alone, % above the reference</source>
        <translation>Strategie allein, % über der Referenz</translation>
    </message>
    <message>
        <source> · policy alone %1 % above the reference</source>
        <translation> · Strategie allein %1 % über der Referenz</translation>
    </message>
    <message>
        <source>From the generalist</source>
        <translation>Vom allgemeinen Modell</translation>
    </message>
    <message>
        <source>Start from the built-in generalist model, trained on generated floors (what solver dqn uses before any training), and fine-tune it for this plan. Off: start from random weights. Graph state only.</source>
        <translation>Vom eingebauten allgemeinen Modell ausgehen, das auf erzeugten Grundrissen trainiert wurde (das nutzt der Solver dqn vor jedem Training), und es für diesen Plan nachtrainieren. Aus: mit zufälligen Gewichten beginnen. Nur für den Graph-Zustand.</translation>
    </message>
</context>
<context>
    <name>fc::ui::Translations</name>
    <message>
        <source>System language</source>
        <translation>Systemsprache</translation>
    </message>
</context>
<context>
    <name>fc::ui::WelcomeDialog</name>
    <message>
        <source>Show this page at start</source>
        <translation>Diese Seite beim Start zeigen</translation>
    </message>
    <message>
        <source>Welcome to FloorCover</source>
        <translation>Willkommen bei FloorCover</translation>
    </message>
    <message>
        <source>&lt;h2&gt;Welcome to FloorCover&lt;/h2&gt;&lt;p&gt;FloorCover plans the path a cleaning or disinfection robot drives to cover a floor:&lt;/p&gt;&lt;ol&gt;&lt;li&gt;&lt;b&gt;Bring a floor plan&lt;/b&gt;: draw it, import a CAD drawing or the robot&apos;s map, or try a sample below.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Choose the rooms&lt;/b&gt; to clean and where the robot starts.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Check the path&lt;/b&gt; and its time, then export it for the robot or print a report.&lt;/li&gt;&lt;/ol&gt;</source>
        <translation>&lt;h2&gt;Willkommen bei FloorCover&lt;/h2&gt;&lt;p&gt;FloorCover plant den Pfad, den ein Reinigungs- oder Desinfektionsroboter fährt, um eine Fläche abzudecken:&lt;/p&gt;&lt;ol&gt;&lt;li&gt;&lt;b&gt;Grundriss bereitstellen&lt;/b&gt;: Zeichnen Sie ihn, importieren Sie eine CAD-Zeichnung oder die Karte des Roboters, oder probieren Sie unten ein Beispiel aus.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Räume wählen&lt;/b&gt;, die gereinigt werden sollen, und festlegen, wo der Roboter startet.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Pfad prüfen&lt;/b&gt; samt Dauer, dann für den Roboter exportieren oder einen Bericht drucken.&lt;/li&gt;&lt;/ol&gt;</translation>
    </message>
    <message>
        <source>Double-click a sample to open it</source>
        <translation>Doppelklicken Sie auf ein Beispiel, um es zu öffnen</translation>
    </message>
    <message>
        <source>Open Sample</source>
        <translation>Beispiel öffnen</translation>
    </message>
    <message>
        <source>Open the selected sample plan</source>
        <translation>Den ausgewählten Beispielplan öffnen</translation>
    </message>
    <message>
        <source>Draw a New Floor</source>
        <translation>Neuen Grundriss zeichnen</translation>
    </message>
    <message>
        <source>Start an empty drawing with the Draw Boundary tool</source>
        <translation>Eine leere Zeichnung mit dem Werkzeug „Außenwand zeichnen“ beginnen</translation>
    </message>
    <message>
        <source>Import a Drawing or Map…</source>
        <translation>Zeichnung oder Karte importieren…</translation>
    </message>
    <message>
        <source>DXF drawings, the robot&apos;s occupancy map (.yaml), WKT, GeoJSON or 3D building models</source>
        <translation>DXF-Zeichnungen, die Belegungskarte des Roboters (.yaml), WKT, GeoJSON oder 3D-Gebäudemodelle</translation>
    </message>
    <message>
        <source>Open a Project…</source>
        <translation>Projekt öffnen…</translation>
    </message>
    <message>
        <source>Open a saved .fcproj or .geojson</source>
        <translation>Eine gespeicherte .fcproj- oder .geojson-Datei öffnen</translation>
    </message>
    <message>
        <source>Getting Started</source>
        <translation>Erste Schritte</translation>
    </message>
    <message>
        <source>A short guide through a first plan (F1)</source>
        <translation>Eine kurze Anleitung durch einen ersten Plan (F1)</translation>
    </message>
    <message>
        <source>Help &gt; Welcome Page shows it again at any time</source>
        <translation>Hilfe &gt; Willkommensseite zeigt sie jederzeit wieder an</translation>
    </message>
    <message>
        <source>Close this page</source>
        <translation>Diese Seite schließen</translation>
    </message>
    <message>
        <source>&lt;b&gt;Sample plans&lt;/b&gt;</source>
        <translation>&lt;b&gt;Beispielpläne&lt;/b&gt;</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Coverage path planning for floor plans</source>
        <translation>Abdeckungspfadplanung für Grundrisse</translation>
    </message>
    <message>
        <source>Render the main window with overlays and a planned path to FILE (PNG) and exit.</source>
        <translation>Das Hauptfenster mit Überlagerungen und einem geplanten Pfad in DATEI (PNG) zeichnen und beenden.</translation>
    </message>
    <message>
        <source>FILE</source>
        <translation>DATEI</translation>
    </message>
    <message>
        <source>A .fcproj or .geojson file.</source>
        <translation>Eine .fcproj- oder .geojson-Datei.</translation>
    </message>
    <message>
        <source>Of a GeoJSON site of several buildings, open building K (1 = the largest) instead of asking.</source>
        <translation>Von einem GeoJSON-Gelände mit mehreren Gebäuden Gebäude K öffnen (1 = das größte), statt zu fragen.</translation>
    </message>
</context>
</TS>

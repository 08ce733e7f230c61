<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="fr_FR">
<context>
    <name>PlannerMessages</name>
    <message>
        <source>The exact solver could not prove the best order of %1 cells within its budget (%2). Choose the heuristic solver in the Planning panel.</source>
        <translation>Le solveur exact n’a pas pu prouver le meilleur ordre de %1 cellules dans son budget (%2). Choisissez le solveur heuristique dans le panneau Planification.</translation>
    </message>
    <message>
        <source>These rooms have %1 cells, and the exact solver orders at most %2. Choose the heuristic solver in the Planning panel.</source>
        <translation>Ces pièces ont %1 cellules, et le solveur exact en ordonne au plus %2. Choisissez le solveur heuristique dans le panneau Planification.</translation>
    </message>
    <message>
        <source>Obstacle %1 crosses the outer wall near %2.</source>
        <translation>L’obstacle %1 traverse le mur extérieur près de %2.</translation>
    </message>
    <message>
        <source>Obstacle %1 touches the outer wall at %2; obstacles must lie inside the walls.</source>
        <translation>L’obstacle %1 touche le mur extérieur en %2 ; les obstacles doivent se trouver à l’intérieur des murs.</translation>
    </message>
    <message>
        <source>Obstacles %1 and %2 overlap near %3.</source>
        <translation>Les obstacles %1 et %2 se chevauchent près de %3.</translation>
    </message>
    <message>
        <source>Obstacles %1 and %2 touch at %3; draw them as one obstacle.</source>
        <translation>Les obstacles %1 et %2 se touchent en %3 ; dessinez-les comme un seul obstacle.</translation>
    </message>
    <message>
        <source>Obstacle %1 lies outside the walls, near %2.</source>
        <translation>L’obstacle %1 est en dehors des murs, près de %2.</translation>
    </message>
    <message>
        <source>Obstacle %1 lies inside obstacle %2.</source>
        <translation>L’obstacle %1 est à l’intérieur de l’obstacle %2.</translation>
    </message>
    <message>
        <source>%1 crosses itself near %2.</source>
        <translation>%1 se recoupe près de %2.</translation>
    </message>
    <message>
        <source>%1 touches itself at %2.</source>
        <translation>%1 touche son propre tracé en %2.</translation>
    </message>
    <message>
        <source>%1 folds back on itself (a spike) at %2.</source>
        <translation>%1 revient sur son propre tracé (une pointe) en %2.</translation>
    </message>
    <message>
        <source>Rooms “%1” and “%2” overlap by %3 m² near %4.</source>
        <translation>Les pièces « %1 » et « %2 » se chevauchent sur %3 m² près de %4.</translation>
    </message>
    <message>
        <source>Rooms “%1” and “%2” overlap by %3 m².</source>
        <translation>Les pièces « %1 » et « %2 » se chevauchent sur %3 m².</translation>
    </message>
    <message>
        <source>Room “%1” lies outside the walls.</source>
        <translation>La pièce « %1 » est en dehors des murs.</translation>
    </message>
    <message>
        <source>Room “%1” lies inside obstacle %2.</source>
        <translation>La pièce « %1 » est à l’intérieur de l’obstacle %2.</translation>
    </message>
    <message>
        <source>Two rooms are named “%1”: rename one.</source>
        <translation>Deux pièces s’appellent « %1 » : renommez-en une.</translation>
    </message>
    <message>
        <source>%1 cells (%2 m²) cannot be reached from the start and are left out.</source>
        <translation>%1 cellules (%2 m²) ne sont pas accessibles depuis le départ et sont laissées de côté.</translation>
    </message>
    <message>
        <source>Room %1 cannot be reached from the start and is left out.</source>
        <translation>La pièce %1 n’est pas accessible depuis le départ et est laissée de côté.</translation>
    </message>
    <message>
        <source>%1 m² (%2 % of the selected floor) the robot could clean but the path misses.</source>
        <translation>%1 m² (%2 % du sol sélectionné) que le robot pourrait nettoyer mais que le trajet ne couvre pas.</translation>
    </message>
    <message>
        <source>%1 m² (%2 % of the selected floor) the robot cannot reach (gaps narrower than the robot, corners beyond its head).</source>
        <translation>%1 m² (%2 % du sol sélectionné) que le robot ne peut pas atteindre (passages plus étroits que le robot, coins hors de portée de sa tête de nettoyage).</translation>
    </message>
    <message>
        <source>No selected room can be reached from the start: move the start (Place Start) or pick other rooms.</source>
        <translation>Aucune pièce sélectionnée n’est accessible depuis le départ : déplacez le départ (Placer le départ) ou choisissez d’autres pièces.</translation>
    </message>
    <message>
        <source>The end cannot be reached from the start: move one of them.</source>
        <translation>L’arrivée n’est pas accessible depuis le départ : déplacez l’un des deux.</translation>
    </message>
    <message>
        <source>The selected rooms have no floor the robot can clean: pick other rooms or a smaller robot.</source>
        <translation>Les pièces sélectionnées n’ont aucune surface que le robot puisse nettoyer : choisissez d’autres pièces ou un robot plus petit.</translation>
    </message>
    <message>
        <source>The robot diameter L (%1 m) is larger than the coverage width W (%2 m): L ≤ W ≤ D.</source>
        <translation>Le diamètre du robot L (%1 m) est plus grand que la largeur de couverture W (%2 m) : il faut L ≤ W ≤ D.</translation>
    </message>
    <message>
        <source>The coverage width W (%1 m) is larger than the cleaning diameter D (%2 m): L ≤ W ≤ D.</source>
        <translation>La largeur de couverture W (%1 m) est plus grande que le diamètre de nettoyage D (%2 m) : il faut L ≤ W ≤ D.</translation>
    </message>
    <message>
        <source>The outer wall</source>
        <translation>Le mur extérieur</translation>
    </message>
    <message>
        <source>Obstacle %1</source>
        <translation>L’obstacle %1</translation>
    </message>
    <message>
        <source>Room “%1”</source>
        <translation>La pièce « %1 »</translation>
    </message>
    <message>
        <source>Obstacles %1 and %2 are the same: delete one of them.</source>
        <translation>Les obstacles %1 et %2 sont identiques : supprimez l’un d’eux.</translation>
    </message>
    <message>
        <source>Room “%1” covers only obstacles: there is no floor in it to clean.</source>
        <translation>La pièce « %1 » ne couvre que des obstacles : il n’y a rien à nettoyer.</translation>
    </message>
    <message>
        <source>Room %1 has no name: give it one.</source>
        <translation>La pièce %1 n’a pas de nom : donnez-lui-en un.</translation>
    </message>
    <message>
        <source>The free floor (%1 m²) is smaller than the robot (%2 m², L = %3 m).</source>
        <translation>La surface libre (%1 m²) est plus petite que le robot (%2 m², L = %3 m).</translation>
    </message>
    <message>
        <source>%1 (feature %2)</source>
        <translation>%1 (entité %2)</translation>
    </message>
    <message>
        <source>%1 (hole %2 in the outer wall)</source>
        <translation>%1 (trou %2 du mur extérieur)</translation>
    </message>
    <message>
        <source>%1 (outer wall)</source>
        <translation>%1 (mur extérieur)</translation>
    </message>
    <message>
        <source>%1 (obstacle)</source>
        <translation>%1 (obstacle)</translation>
    </message>
    <message>
        <source>%1 (room)</source>
        <translation>%1 (pièce)</translation>
    </message>
    <message>
        <source>A room</source>
        <translation>Une pièce</translation>
    </message>
    <message>
        <source>An unnamed room</source>
        <translation>Une pièce sans nom</translation>
    </message>
    <message>
        <source>Room %1</source>
        <translation>La pièce %1</translation>
    </message>
    <message>
        <source>Feature %1</source>
        <translation>L’entité %1</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1 : %2</translation>
    </message>
    <message>
        <source>The free floor (%1 m²) is smaller than one coverage square W² (%2 m²): make the coverage width W smaller in the Planning panel.</source>
        <translation>La surface libre (%1 m²) est plus petite qu’un carré de couverture W² (%2 m²) : réduisez la largeur de couverture W dans le panneau Planification.</translation>
    </message>
    <message>
        <source>%1: vertex %2 has a coordinate that is not a finite number.</source>
        <translation>%1 : le sommet %2 a une coordonnée qui n’est pas un nombre fini.</translation>
    </message>
    <message>
        <source>%1 has two vertices on top of each other at %3 (vertex %2): delete one of them (Edit Vertices, right-click).</source>
        <translation>%1 a deux sommets superposés en %3 (sommet %2) : supprimez-en un (Modifier les sommets, clic droit).</translation>
    </message>
    <message>
        <source>%1 has no area: all its vertices lie on one line.</source>
        <translation>%1 n’a pas de surface : tous ses sommets sont alignés.</translation>
    </message>
    <message>
        <source>The robot diameter L must be a positive number, not %1: change it in the Planning panel.</source>
        <translation>Le diamètre du robot L doit être un nombre positif, pas %1 : modifiez-le dans le panneau Planification.</translation>
    </message>
    <message>
        <source>The coverage width W must be a positive number, not %1: change it in the Planning panel.</source>
        <translation>La largeur de couverture W doit être un nombre positif, pas %1 : modifiez-la dans le panneau Planification.</translation>
    </message>
    <message>
        <source>The cleaning diameter D must be a positive number, not %1: change it in the Planning panel.</source>
        <translation>Le diamètre de nettoyage D doit être un nombre positif, pas %1 : modifiez-le dans le panneau Planification.</translation>
    </message>
    <message>
        <source>The speed must be a positive number, not %1: change it in the Planning panel.</source>
        <translation>La vitesse doit être un nombre positif, pas %1 : modifiez-la dans le panneau Planification.</translation>
    </message>
    <message>
        <source>The robot&apos;s turn time must be zero or positive, not %1.</source>
        <translation>Le temps de rotation du robot doit être nul ou positif, pas %1.</translation>
    </message>
    <message>
        <source>A coverage width W of %1 m is not a plausible robot size: change it in the Planning panel.</source>
        <translation>Une largeur de couverture W de %1 m n’est pas une taille de robot plausible : modifiez-la dans le panneau Planification.</translation>
    </message>
    <message>
        <source>one of the rooms has fewer than three corners</source>
        <translation>l’une des pièces a moins de trois coins</translation>
    </message>
    <message>
        <source>they do not share a border; merge rooms that meet along a wall or a doorway</source>
        <translation>elles n’ont pas de bord commun ; fusionnez des pièces qui se touchent le long d’un mur ou d’un passage</translation>
    </message>
    <message>
        <source>the merged room would fall apart into several pieces</source>
        <translation>la pièce fusionnée serait en plusieurs morceaux</translation>
    </message>
    <message>
        <source>the merged room would enclose a hole; merge the room inside it as well</source>
        <translation>la pièce fusionnée entourerait un trou ; fusionnez aussi la pièce qui s’y trouve</translation>
    </message>
    <message>
        <source>the room has fewer than three corners</source>
        <translation>la pièce a moins de trois coins</translation>
    </message>
    <message>
        <source>drag the cut as a line across the room (Split Room)</source>
        <translation>tracez la coupe comme une ligne à travers la pièce (Diviser la pièce)</translation>
    </message>
    <message>
        <source>the cut does not cross the room; drag it from one wall of the room to another</source>
        <translation>la coupe ne traverse pas la pièce ; tracez-la d’un mur de la pièce à un autre</translation>
    </message>
    <message>
        <source>the cut crosses the room more than once; drag it where one straight line divides the room in two</source>
        <translation>la coupe traverse la pièce plus d’une fois ; tracez-la là où une ligne droite divise la pièce en deux</translation>
    </message>
    <message>
        <source>the cut would cut off only a sliver of the room; drag it across the middle of the room</source>
        <translation>la coupe ne détacherait qu’une mince bande de la pièce ; tracez-la à travers le milieu de la pièce</translation>
    </message>
    <message>
        <source>The sweep angle must be a finite number of degrees: set it in the Planning panel.</source>
        <translation>L’angle de balayage doit être un nombre fini de degrés : réglez-le dans le panneau Planification.</translation>
    </message>
    <message>
        <source>There is no room “%1” in this plan (its rooms: %2): check the rooms to plan in the Planning panel.</source>
        <translation>Ce plan n’a pas de pièce « %1 » (ses pièces : %2) : vérifiez les pièces à planifier dans le panneau Planification.</translation>
    </message>
    <message>
        <source>There is no solver “%1” (available: %2): choose one in the Planning panel.</source>
        <translation>Il n’existe pas de solveur « %1 » (disponibles : %2) : choisissez-en un dans le panneau Planification.</translation>
    </message>
    <message>
        <source>The robot finds no way into room “%1” from the room before it: widen the passage, or sweep the floor at one angle (Sweep in the Planning panel).</source>
        <translation>Le robot ne trouve aucun chemin vers la pièce « %1 » depuis la pièce précédente : élargissez le passage, ou balayez le sol selon un seul angle (Balayage dans le panneau Planification).</translation>
    </message>
    <message>
        <source>Cancelled.</source>
        <translation>Annulé.</translation>
    </message>
    <message>
        <source>The %1 solver was cancelled.</source>
        <translation>Le solveur %1 a été annulé.</translation>
    </message>
    <message>
        <source>The %1 solver cannot reach %2 cells from the start: move the start (Place Start) or pick other rooms.</source>
        <translation>Le solveur %1 ne peut pas atteindre %2 cellules depuis le départ : déplacez le départ (Placer le départ) ou choisissez d’autres pièces.</translation>
    </message>
    <message>
        <source>The %1 solver cannot reach the end from the start: move one of them.</source>
        <translation>Le solveur %1 ne peut pas atteindre l’arrivée depuis le départ : déplacez l’un des deux.</translation>
    </message>
    <message>
        <source>The %1 solver stopped on an internal error (%2): please report it, and choose another solver in the Planning panel meanwhile.</source>
        <translation>Le solveur %1 s’est arrêté sur une erreur interne (%2) : signalez-la, et choisissez en attendant un autre solveur dans le panneau Planification.</translation>
    </message>
    <message>
        <source>The dqn model is inconsistent (its network does not fit its kind of state): train a new model in the Training panel.</source>
        <translation>Le modèle dqn est incohérent (son réseau ne correspond pas à son type d’état) : entraînez un nouveau modèle dans le panneau Entraînement.</translation>
    </message>
    <message>
        <source>The dqn model was trained on a plan of another size: train a model for this plan in the Training panel.</source>
        <translation>Le modèle dqn a été entraîné sur un plan d’une autre taille : entraînez un modèle pour ce plan dans le panneau Entraînement.</translation>
    </message>
    <message>
        <source>The dqn solver cannot plan this query (%1): choose another solver in the Planning panel.</source>
        <translation>Le solveur dqn ne peut pas planifier cette requête (%1) : choisissez un autre solveur dans le panneau Planification.</translation>
    </message>
    <message>
        <source>The dqn solver finds no way to the rooms still to clean: choose another solver in the Planning panel.</source>
        <translation>Le solveur dqn ne trouve aucun chemin vers les pièces restant à nettoyer : choisissez un autre solveur dans le panneau Planification.</translation>
    </message>
    <message>
        <source>The dqn model ran out of steps before it covered the rooms: train it longer in the Training panel, or choose another solver.</source>
        <translation>Le modèle dqn a épuisé ses pas avant de couvrir les pièces : entraînez-le plus longtemps dans le panneau Entraînement, ou choisissez un autre solveur.</translation>
    </message>
    <message>
        <source>The path of the dqn solver does not cover the rooms (an internal error): choose another solver in the Planning panel.</source>
        <translation>Le trajet du solveur dqn ne couvre pas les pièces (une erreur interne) : choisissez un autre solveur dans le panneau Planification.</translation>
    </message>
    <message>
        <source>The plan has no floor the robot can reach: there is nothing to train on.</source>
        <translation>Le plan n’a aucune surface que le robot puisse atteindre : il n’y a rien sur quoi s’entraîner.</translation>
    </message>
    <message>
        <source>The model file is incomplete: load another model or train a new one in the Training panel.</source>
        <translation>Le fichier du modèle est incomplet : chargez un autre modèle ou entraînez-en un nouveau dans le panneau Entraînement.</translation>
    </message>
    <message>
        <source>The model file is damaged: load another model or train a new one in the Training panel.</source>
        <translation>Le fichier du modèle est endommagé : chargez un autre modèle ou entraînez-en un nouveau dans le panneau Entraînement.</translation>
    </message>
    <message>
        <source>This is not a FloorCover dqn model file (.fcdqn).</source>
        <translation>Ce n’est pas un fichier de modèle dqn de FloorCover (.fcdqn).</translation>
    </message>
    <message>
        <source>The model file has format version %1, and this FloorCover reads versions up to %2: update FloorCover or train a new model.</source>
        <translation>Le fichier du modèle est au format version %1, et ce FloorCover lit les versions jusqu’à %2 : mettez FloorCover à jour ou entraînez un nouveau modèle.</translation>
    </message>
    <message>
        <source>The model file cannot be opened: check that it exists and can be read.</source>
        <translation>Le fichier du modèle ne peut pas être ouvert : vérifiez qu’il existe et qu’il est lisible.</translation>
    </message>
    <message>
        <source>This model was trained for another floor plan or robot (%1 corners in %2 cells, sweep angle %3°, coverage width %4 m; this plan has %5 corners in %6 cells): train a model for this plan in the Training panel.</source>
        <translation>Ce modèle a été entraîné pour un autre plan ou un autre robot (%1 coins dans %2 cellules, angle de balayage %3°, largeur de couverture %4 m ; ce plan a %5 coins dans %6 cellules) : entraînez un modèle pour ce plan dans le panneau Entraînement.</translation>
    </message>
    <message>
        <source>There is no such file.</source>
        <translation>Ce fichier n’existe pas.</translation>
    </message>
    <message>
        <source>This is a folder, not a file.</source>
        <translation>C’est un dossier, pas un fichier.</translation>
    </message>
    <message>
        <source>The file cannot be read (%1).</source>
        <translation>Le fichier ne peut pas être lu (%1).</translation>
    </message>
    <message>
        <source>The file cannot be written (%1): choose another folder, or check that this one can be written to.</source>
        <translation>Le fichier ne peut pas être écrit (%1) : choisissez un autre dossier, ou vérifiez que celui-ci est accessible en écriture.</translation>
    </message>
    <message>
        <source>The file name has no extension: FloorCover opens .fcproj projects and .geojson or .json plans; other formats come in with File &gt; Import…</source>
        <translation>Le nom du fichier n’a pas d’extension : FloorCover ouvre les projets .fcproj et les plans .geojson ou .json ; les autres formats passent par Fichier &gt; Importer…</translation>
    </message>
    <message>
        <source>FloorCover opens .fcproj projects and .geojson or .json plans, not “%1” files; other formats come in with File &gt; Import…</source>
        <translation>FloorCover ouvre les projets .fcproj et les plans .geojson ou .json, pas les fichiers « %1 » ; les autres formats passent par Fichier &gt; Importer…</translation>
    </message>
    <message>
        <source>The file is larger than %1, more than FloorCover imports.</source>
        <translation>Le fichier dépasse %1, plus que ce que FloorCover importe.</translation>
    </message>
    <message>
        <source>The file is empty.</source>
        <translation>Le fichier est vide.</translation>
    </message>
    <message>
        <source>The file ends too early (line %1, column %2): it may have been cut off while it was written.</source>
        <translation>Le fichier se termine trop tôt (ligne %1, colonne %2) : il a peut-être été tronqué pendant son écriture.</translation>
    </message>
    <message>
        <source>The file ends too early: it may have been cut off while it was written.</source>
        <translation>Le fichier se termine trop tôt : il a peut-être été tronqué pendant son écriture.</translation>
    </message>
    <message>
        <source>The file is not valid JSON at line %1, column %2 (%3).</source>
        <translation>Le fichier n’est pas du JSON valide à la ligne %1, colonne %2 (%3).</translation>
    </message>
    <message>
        <source>The file is not valid JSON (%1).</source>
        <translation>Le fichier n’est pas du JSON valide (%1).</translation>
    </message>
    <message>
        <source>The number %1 at line %2, column %3 is too large for a coordinate.</source>
        <translation>Le nombre %1 à la ligne %2, colonne %3 est trop grand pour une coordonnée.</translation>
    </message>
    <message>
        <source>The number %1 is too large for a coordinate.</source>
        <translation>Le nombre %1 est trop grand pour une coordonnée.</translation>
    </message>
    <message>
        <source>A number in the file is out of range (%1).</source>
        <translation>Un nombre du fichier est hors limites (%1).</translation>
    </message>
    <message>
        <source>%1: the coordinates must be a list of [x, y] positions, not %2.</source>
        <translation>%1 : les coordonnées doivent être une liste de positions [x, y], pas %2.</translation>
    </message>
    <message>
        <source>%1: vertex %2 is not an [x, y] position but %3.</source>
        <translation>%1 : le sommet %2 n’est pas une position [x, y] mais %3.</translation>
    </message>
    <message>
        <source>%1: vertex %2 has a coordinate that is not a number (%3).</source>
        <translation>%1 : le sommet %2 a une coordonnée qui n’est pas un nombre (%3).</translation>
    </message>
    <message>
        <source>%1 has no geometry.</source>
        <translation>%1 n’a pas de géométrie.</translation>
    </message>
    <message>
        <source>%1: the geometry has no type.</source>
        <translation>%1 : la géométrie n’a pas de type.</translation>
    </message>
    <message>
        <source>%1 is a %2; FloorCover reads plans drawn as polygons.</source>
        <translation>%1 est un %2 ; FloorCover lit les plans dessinés en polygones.</translation>
    </message>
    <message>
        <source>%1: the geometry holds no polygon outline.</source>
        <translation>%1 : la géométrie ne contient aucun contour de polygone.</translation>
    </message>
    <message>
        <source>%1: the room name (properties.name) must be text, not %2.</source>
        <translation>%1 : le nom de la pièce (properties.name) doit être du texte, pas %2.</translation>
    </message>
    <message>
        <source>%1 has no name: rooms need one in properties.name.</source>
        <translation>%1 n’a pas de nom : les pièces en ont besoin d’un dans properties.name.</translation>
    </message>
    <message>
        <source>The file holds %1 buildings (outer walls of %2 m², largest first), and a plan holds one: choose one as you open it.</source>
        <translation>Le fichier contient %1 bâtiments (murs extérieurs de %2 m², le plus grand d’abord), et un plan n’en contient qu’un : choisissez-en un à l’ouverture.</translation>
    </message>
    <message>
        <source>%1 has a hole; floor inside an obstacle is not supported.</source>
        <translation>%1 a un trou ; une surface libre à l’intérieur d’un obstacle n’est pas prise en charge.</translation>
    </message>
    <message>
        <source>Two rooms are named “%1” (features %2 and %3): rename one.</source>
        <translation>Deux pièces s’appellent « %1 » (entités %2 et %3) : renommez-en une.</translation>
    </message>
    <message>
        <source>%1 has %2 separate parts: split it into rooms with names of their own.</source>
        <translation>%1 a %2 parties séparées : divisez-la en pièces ayant chacune son nom.</translation>
    </message>
    <message>
        <source>%1 has a hole: draw the hole as an obstacle instead.</source>
        <translation>%1 a un trou : dessinez plutôt le trou comme un obstacle.</translation>
    </message>
    <message>
        <source>The file is not a GeoJSON FeatureCollection, the form in which FloorCover reads plans.</source>
        <translation>Le fichier n’est pas une FeatureCollection GeoJSON, la forme sous laquelle FloorCover lit les plans.</translation>
    </message>
    <message>
        <source>The GeoJSON file has no list of features.</source>
        <translation>Le fichier GeoJSON n’a pas de liste d’entités (features).</translation>
    </message>
    <message>
        <source>%1 is not a GeoJSON Feature.</source>
        <translation>%1 n’est pas une Feature GeoJSON.</translation>
    </message>
    <message>
        <source>%1: its properties must be an object.</source>
        <translation>%1 : ses propriétés (properties) doivent être un objet.</translation>
    </message>
    <message>
        <source>%1 has no role: set properties.role to boundary, obstacle or room.</source>
        <translation>%1 n’a pas de rôle : donnez à properties.role la valeur boundary, obstacle ou room.</translation>
    </message>
    <message>
        <source>%1: the role (properties.role) must be text, not %2.</source>
        <translation>%1 : le rôle (properties.role) doit être du texte, pas %2.</translation>
    </message>
    <message>
        <source>%1 has the unknown role “%2”: use boundary, obstacle or room.</source>
        <translation>%1 a le rôle inconnu « %2 » : utilisez boundary, obstacle ou room.</translation>
    </message>
    <message>
        <source>The plan has no outer wall: one feature needs properties.role = &quot;boundary&quot;.</source>
        <translation>Le plan n’a pas de mur extérieur : une entité doit avoir properties.role = &quot;boundary&quot;.</translation>
    </message>
    <message>
        <source>In the project file, %1 must be a finite number, not %2.</source>
        <translation>Dans le fichier de projet, %1 doit être un nombre fini, pas %2.</translation>
    </message>
    <message>
        <source>In the project file, %1 must be an object.</source>
        <translation>Dans le fichier de projet, %1 doit être un objet.</translation>
    </message>
    <message>
        <source>In the project file, %1 must be [x, y] or null, not %2.</source>
        <translation>Dans le fichier de projet, %1 doit être [x, y] ou null, pas %2.</translation>
    </message>
    <message>
        <source>In the project file, %1 has a coordinate that is not a finite number.</source>
        <translation>Dans le fichier de projet, %1 a une coordonnée qui n’est pas un nombre fini.</translation>
    </message>
    <message>
        <source>The project&apos;s plan has no outer wall (boundary).</source>
        <translation>Le plan du projet n’a pas de mur extérieur (boundary).</translation>
    </message>
    <message>
        <source>In the project file, %1 must be a list.</source>
        <translation>Dans le fichier de projet, %1 doit être une liste.</translation>
    </message>
    <message>
        <source>%1 has no outline.</source>
        <translation>%1 n’a pas de contour.</translation>
    </message>
    <message>
        <source>In the project file, plan.epsg must be an EPSG code (a positive whole number), not %1.</source>
        <translation>Dans le fichier de projet, plan.epsg doit être un code EPSG (un entier positif), pas %1.</translation>
    </message>
    <message>
        <source>The file is not a FloorCover project.</source>
        <translation>Le fichier n’est pas un projet FloorCover.</translation>
    </message>
    <message>
        <source>The project file does not say its format version.</source>
        <translation>Le fichier de projet n’indique pas sa version de format.</translation>
    </message>
    <message>
        <source>The project was saved by a newer FloorCover (format version %1; this one reads up to %2): update FloorCover.</source>
        <translation>Le projet a été enregistré par un FloorCover plus récent (version de format %1 ; celui-ci lit jusqu’à %2) : mettez FloorCover à jour.</translation>
    </message>
    <message>
        <source>The project file has an invalid format version (%1).</source>
        <translation>Le fichier de projet a une version de format invalide (%1).</translation>
    </message>
    <message>
        <source>The project file holds no plan.</source>
        <translation>Le fichier de projet ne contient aucun plan.</translation>
    </message>
    <message>
        <source>In the project file, sweep.%1 must be true or false.</source>
        <translation>Dans le fichier de projet, sweep.%1 doit valoir true ou false.</translation>
    </message>
    <message>
        <source>In the project file, sweep.room_angles must give each room&apos;s sweep angle in degrees.</source>
        <translation>Dans le fichier de projet, sweep.room_angles doit donner l’angle de balayage de chaque pièce en degrés.</translation>
    </message>
    <message>
        <source>In the project file, the sweep angle of room “%1” must be a finite number of degrees, not %2.</source>
        <translation>Dans le fichier de projet, l’angle de balayage de la pièce « %1 » doit être un nombre fini de degrés, pas %2.</translation>
    </message>
    <message>
        <source>In the project file, solver must be the name of a solver, not %1.</source>
        <translation>Dans le fichier de projet, solver doit être le nom d’un solveur, pas %1.</translation>
    </message>
    <message>
        <source>In the project file, selectedRooms must be a list of room names.</source>
        <translation>Dans le fichier de projet, selectedRooms doit être une liste de noms de pièces.</translation>
    </message>
    <message>
        <source>FloorCover cannot export to “%1” (it exports %2).</source>
        <translation>FloorCover ne peut pas exporter en « %1 » (il exporte %2).</translation>
    </message>
    <message>
        <source>FloorCover cannot export “%1”: it exports the path, the plan or the zones.</source>
        <translation>FloorCover ne peut pas exporter « %1 » : il exporte le trajet, le plan ou les zones.</translation>
    </message>
    <message>
        <source>The %1 format cannot hold the path: choose another format.</source>
        <translation>Le format %1 ne peut pas contenir le trajet : choisissez un autre format.</translation>
    </message>
    <message>
        <source>The %1 format cannot hold the plan: choose another format.</source>
        <translation>Le format %1 ne peut pas contenir le plan : choisissez un autre format.</translation>
    </message>
    <message>
        <source>The %1 format cannot hold the zones: choose another format.</source>
        <translation>Le format %1 ne peut pas contenir les zones : choisissez un autre format.</translation>
    </message>
    <message>
        <source>FloorCover does not know this export format: choose one of the formats offered.</source>
        <translation>FloorCover ne connaît pas ce format d’export : choisissez l’un des formats proposés.</translation>
    </message>
    <message>
        <source>FloorCover cannot import “.%1” files (it imports %2).</source>
        <translation>FloorCover ne peut pas importer les fichiers « .%1 » (il importe %2).</translation>
    </message>
    <message>
        <source>FloorCover cannot import “.%1” files.</source>
        <translation>FloorCover ne peut pas importer les fichiers « .%1 ».</translation>
    </message>
    <message>
        <source>“Close gaps up to” must be between 0 and 1000 m.</source>
        <translation>« Fermer les écarts jusqu’à » doit être compris entre 0 et 1000 m.</translation>
    </message>
    <message>
        <source>The plan needs repair (Plan &gt; Repair Plan, after the import): %1</source>
        <translation>Le plan doit être réparé (Planifier &gt; Réparer le plan, après l’import) : %1</translation>
    </message>
    <message>
        <source>The map&apos;s start pose (%1, %2) is not on the free floor; it was not used.</source>
        <translation>La pose de départ de la carte (%1, %2) n’est pas sur la surface libre ; elle n’a pas été utilisée.</translation>
    </message>
    <message>
        <source>The map image&apos;s pixels are %1; FloorCover reads 1- to 16-bit grey or colour images.</source>
        <translation>Les pixels de l’image de la carte sont %1 ; FloorCover lit les images en gris ou en couleur de 1 à 16 bits.</translation>
    </message>
    <message>
        <source>The map image %1 is not a readable PNG, PGM, BMP or TIFF image.</source>
        <translation>L’image de la carte %1 n’est pas une image PNG, PGM, BMP ou TIFF lisible.</translation>
    </message>
    <message>
        <source>The map image is empty.</source>
        <translation>L’image de la carte est vide.</translation>
    </message>
    <message>
        <source>The map image has more than %1 pixels, more than FloorCover reads.</source>
        <translation>L’image de la carte a plus de %1 pixels, plus que ce que FloorCover lit.</translation>
    </message>
    <message>
        <source>The map image cannot be read (%1).</source>
        <translation>L’image de la carte ne peut pas être lue (%1).</translation>
    </message>
    <message>
        <source>The map image uses a colour that its palette lacks.</source>
        <translation>L’image de la carte utilise une couleur absente de sa palette.</translation>
    </message>
    <message>
        <source>The map image %1 named in the YAML file is missing: keep it next to the YAML file.</source>
        <translation>L’image de la carte %1 nommée dans le fichier YAML est introuvable : placez-la à côté du fichier YAML.</translation>
    </message>
    <message>
        <source>Every cell of the map is unknown: the map shows nothing.</source>
        <translation>Toutes les cellules de la carte sont inconnues : la carte ne montre rien.</translation>
    </message>
    <message>
        <source>The map has no free floor.</source>
        <translation>La carte n’a pas de surface libre.</translation>
    </message>
    <message>
        <source>Cleaning the map left no free floor (its free cells are specks): lower “Drop islands below” under Clean the map.</source>
        <translation>Le nettoyage de la carte n’a laissé aucune surface libre (ses cellules libres sont des taches) : diminuez « Écarter les îlots sous » dans Nettoyer la carte.</translation>
    </message>
    <message>
        <source>The free floor is thinner than a pixel everywhere.</source>
        <translation>La surface libre est partout plus fine qu’un pixel.</translation>
    </message>
    <message>
        <source>In the map&apos;s YAML file, %1 “%2” is not a number.</source>
        <translation>Dans le fichier YAML de la carte, %1 « %2 » n’est pas un nombre.</translation>
    </message>
    <message>
        <source>In the map&apos;s YAML file, %1 must be a list [%2].</source>
        <translation>Dans le fichier YAML de la carte, %1 doit être une liste [%2].</translation>
    </message>
    <message>
        <source>In the map&apos;s YAML file, %1 needs %2 numbers, not %3.</source>
        <translation>Dans le fichier YAML de la carte, %1 demande %2 nombres, pas %3.</translation>
    </message>
    <message>
        <source>In the map&apos;s YAML file, %1 “%2” is not 0/1 or true/false.</source>
        <translation>Dans le fichier YAML de la carte, %1 « %2 » n’est ni 0/1 ni true/false.</translation>
    </message>
    <message>
        <source>The map&apos;s YAML file is larger than 1 MiB; a ROS map&apos;s is far smaller.</source>
        <translation>Le fichier YAML de la carte dépasse 1 Mio ; celui d’une carte ROS est bien plus petit.</translation>
    </message>
    <message>
        <source>Line %1 of the map&apos;s YAML file is not of the form “key: value”.</source>
        <translation>La ligne %1 du fichier YAML de la carte n’est pas de la forme « key: value ».</translation>
    </message>
    <message>
        <source>The YAML file names no image (image:): it is not a ROS map_server map.</source>
        <translation>Le fichier YAML ne nomme aucune image (image:) : ce n’est pas une carte ROS map_server.</translation>
    </message>
    <message>
        <source>The map&apos;s resolution is missing or not a positive size in metres.</source>
        <translation>La résolution de la carte manque ou n’est pas une taille positive en mètres.</translation>
    </message>
    <message>
        <source>A resolution of %1 m per cell is not an occupancy map&apos;s (1 mm to 1 m).</source>
        <translation>Une résolution de %1 m par cellule n’est pas celle d’une carte d’occupation (1 mm à 1 m).</translation>
    </message>
    <message>
        <source>The map has no origin [x, y, yaw].</source>
        <translation>La carte n’a pas d’origine [x, y, yaw].</translation>
    </message>
    <message>
        <source>The map&apos;s origin [%1] lies far outside any map frame.</source>
        <translation>L’origine de la carte [%1] est très loin de tout repère de carte.</translation>
    </message>
    <message>
        <source>The map&apos;s thresholds must satisfy 0 ≤ free_thresh &lt; occupied_thresh ≤ 1.</source>
        <translation>Les seuils de la carte doivent vérifier 0 ≤ free_thresh &lt; occupied_thresh ≤ 1.</translation>
    </message>
    <message>
        <source>The map&apos;s mode “%1” is unknown: it must be trinary, scale or raw.</source>
        <translation>Le mode « %1 » de la carte est inconnu : il doit être trinary, scale ou raw.</translation>
    </message>
    <message>
        <source>The map image is not a PGM or PBM image.</source>
        <translation>L’image de la carte n’est pas une image PGM ou PBM.</translation>
    </message>
    <message>
        <source>In the PGM image&apos;s header, %1 “%2” is not a number.</source>
        <translation>Dans l’en-tête de l’image PGM, %1 « %2 » n’est pas un nombre.</translation>
    </message>
    <message>
        <source>The PGM image&apos;s header has a bad size or maximum value.</source>
        <translation>L’en-tête de l’image PGM a une taille ou une valeur maximale invalide.</translation>
    </message>
    <message>
        <source>The %1 image&apos;s data is cut short or damaged.</source>
        <translation>Les données de l’image %1 sont tronquées ou endommagées.</translation>
    </message>
    <message>
        <source>This FloorCover lacks GDAL&apos;s in-memory drivers: reinstall FloorCover.</source>
        <translation>Il manque à ce FloorCover les pilotes en mémoire de GDAL : réinstallez FloorCover.</translation>
    </message>
    <message>
        <source>The map image does not fit in memory.</source>
        <translation>L’image de la carte ne tient pas en mémoire.</translation>
    </message>
    <message>
        <source>The free floor falls into more than %1 pieces: clean the map more (Clean the map).</source>
        <translation>La surface libre se divise en plus de %1 morceaux : nettoyez davantage la carte (Nettoyer la carte).</translation>
    </message>
    <message>
        <source>Tracing the free floor failed (%1).</source>
        <translation>Le tracé de la surface libre a échoué (%1).</translation>
    </message>
    <message>
        <source>Smoothing the outline of the free floor failed.</source>
        <translation>Le lissage du contour de la surface libre a échoué.</translation>
    </message>
    <message>
        <source>No free floor is left to import.</source>
        <translation>Il ne reste aucune surface libre à importer.</translation>
    </message>
    <message>
        <source>The obstacles could not be merged (their outlines are invalid).</source>
        <translation>Les obstacles n’ont pas pu être fusionnés (leurs contours sont invalides).</translation>
    </message>
    <message>
        <source>The obstacles could not be cut out of the outer wall.</source>
        <translation>Les obstacles n’ont pas pu être découpés dans le mur extérieur.</translation>
    </message>
    <message>
        <source>No closed outline for the outer wall; not closed: %1. A larger “Close gaps up to” may close them.</source>
        <translation>Aucun contour fermé pour le mur extérieur ; non fermés : %1. Une valeur plus grande de « Fermer les écarts jusqu’à » peut les fermer.</translation>
    </message>
    <message>
        <source>No closed outline for the outer wall: give the layer of the walls the role Boundary, or close its gaps with “Close gaps up to”.</source>
        <translation>Aucun contour fermé pour le mur extérieur : donnez au calque des murs le rôle Contour, ou fermez ses écarts avec « Fermer les écarts jusqu’à ».</translation>
    </message>
    <message>
        <source>The plan has no outer wall to repair: draw one first.</source>
        <translation>Le plan n’a pas de mur extérieur à réparer : dessinez-en d’abord un.</translation>
    </message>
    <message>
        <source>The outer wall encloses no area.</source>
        <translation>Le mur extérieur n’entoure aucune surface.</translation>
    </message>
    <message>
        <source>The outer wall crossed or touched itself: it was split there.</source>
        <translation>Le mur extérieur se croisait ou se touchait : il a été divisé à cet endroit.</translation>
    </message>
    <message>
        <source>Obstacles were merged, clipped to the outer wall or joined to it: %1 before, %2 after.</source>
        <translation>Des obstacles ont été fusionnés, coupés au mur extérieur ou joints à lui : %1 avant, %2 après.</translation>
    </message>
    <message>
        <source>%1 lay outside the floor or under other rooms and was removed.</source>
        <translation>%1 était hors du sol ou sous d’autres pièces et a été supprimée.</translation>
    </message>
    <message>
        <source>%1 was reshaped to fit the floor (%2 m² before, %3 m² after).</source>
        <translation>%1 a été redessinée pour tenir dans le sol (%2 m² avant, %3 m² après).</translation>
    </message>
    <message>
        <source>%1 was renamed “%2”.</source>
        <translation>%1 a été renommée « %2 ».</translation>
    </message>
    <message>
        <source>The WKT text begins with SRID= but has no “;” after the code.</source>
        <translation>Le texte WKT commence par SRID= mais n’a pas de « ; » après le code.</translation>
    </message>
    <message>
        <source>The SRID of the WKT text is not a number.</source>
        <translation>Le SRID du texte WKT n’est pas un nombre.</translation>
    </message>
    <message>
        <source>The file is not valid WKT.</source>
        <translation>Le fichier n’est pas du WKT valide.</translation>
    </message>
    <message>
        <source>There is more text after the WKT geometry.</source>
        <translation>Du texte suit la géométrie WKT.</translation>
    </message>
    <message>
        <source>The WKT geometry is a %1, not a POLYGON or MULTIPOLYGON.</source>
        <translation>La géométrie WKT est un %1, pas un POLYGON ou MULTIPOLYGON.</translation>
    </message>
    <message>
        <source>The WKT polygon is empty.</source>
        <translation>Le polygone WKT est vide.</translation>
    </message>
    <message>
        <source>The holes of polygon %1 (a room) were left out.</source>
        <translation>Les trous du polygone %1 (une pièce) ont été écartés.</translation>
    </message>
    <message>
        <source>The file is not a readable DXF drawing (%1).</source>
        <translation>Le fichier n’est pas un dessin DXF lisible (%1).</translation>
    </message>
    <message>
        <source>The file is not a readable DXF drawing.</source>
        <translation>Le fichier n’est pas un dessin DXF lisible.</translation>
    </message>
    <message>
        <source>The drawing has more than %1 vertices, more than FloorCover imports.</source>
        <translation>Le dessin a plus de %1 sommets, plus que ce que FloorCover importe.</translation>
    </message>
    <message>
        <source>The drawing has more than %1 open lines, more than FloorCover imports.</source>
        <translation>Le dessin a plus de %1 lignes ouvertes, plus que ce que FloorCover importe.</translation>
    </message>
    <message>
        <source>The drawing has more than %1 entities, more than FloorCover imports.</source>
        <translation>Le dessin a plus de %1 entités, plus que ce que FloorCover importe.</translation>
    </message>
    <message>
        <source>A coordinate on layer “%1” is not a finite number.</source>
        <translation>Une coordonnée du calque « %1 » n’est pas un nombre fini.</translation>
    </message>
    <message>
        <source>The drawing does not say its unit ($INSUNITS): it was read in metres; correct Units if it is not.</source>
        <translation>Le dessin n’indique pas son unité ($INSUNITS) : il a été lu en mètres ; corrigez Unité si ce n’est pas le cas.</translation>
    </message>
    <message>
        <source>The drawing&apos;s unit ($INSUNITS %1) is unitless or unknown: it was read in metres; correct Units if it is not.</source>
        <translation>L’unité du dessin ($INSUNITS %1) est sans unité ou inconnue : il a été lu en mètres ; corrigez Unité si ce n’est pas le cas.</translation>
    </message>
    <message>
        <source>The drawing is empty.</source>
        <translation>Le dessin est vide.</translation>
    </message>
    <message>
        <source>The block leg must be a positive length in metres: change it in the Tiling Robot panel.</source>
        <translation>Le côté de bloc doit être une longueur positive en mètres : modifiez-le dans le panneau Robot à pavage.</translation>
    </message>
    <message>
        <source>Waypoints are exported as .csv or .json files, not as “%1”.</source>
        <translation>Les points de passage s’exportent en fichiers .csv ou .json, pas en « %1 ».</translation>
    </message>
    <message>
        <source>The exact ordering handles at most %1 waypoints, and this floor has %2: choose another ordering in the Tiling Robot panel.</source>
        <translation>L’ordre exact traite au plus %1 points de passage, et ce sol en a %2 : choisissez un autre ordre dans le panneau Robot à pavage.</translation>
    </message>
    <message>
        <source>There is no ordering “%1” (available: %2).</source>
        <translation>Il n’existe pas d’ordre « %1 » (disponibles : %2).</translation>
    </message>
    <message>
        <source>%1 has too few different vertices (%2); an outline needs at least three.</source>
        <translation>%1 a trop peu de sommets distincts (%2) ; un contour en demande au moins trois.</translation>
    </message>
    <message>
        <source>Pieces of floor not connected to the largest, left out: %1 (%2 m²).</source>
        <translation>Morceaux de sol non reliés au plus grand, écartés : %1 (%2 m²).</translation>
    </message>
    <message>
        <source>Closed outlines outside the outer wall, left out: %1.</source>
        <translation>Contours fermés hors du mur extérieur, écartés : %1.</translation>
    </message>
    <message>
        <source>Room outlines outside the outer wall, left out: %1.</source>
        <translation>Contours de pièces hors du mur extérieur, écartés : %1.</translation>
    </message>
    <message>
        <source>Obstacles without area, removed: %1.</source>
        <translation>Obstacles sans surface, supprimés : %1.</translation>
    </message>
    <message>
        <source>Obstacles that crossed themselves, split where they cross: %1.</source>
        <translation>Obstacles qui se croisaient eux-mêmes, divisés à leurs croisements : %1.</translation>
    </message>
    <message>
        <source>Entities left out on layer “%1” (its role is Ignored): %2.</source>
        <translation>Entités écartées du calque « %1 » (son rôle est Ignoré) : %2.</translation>
    </message>
    <message>
        <source>Entities without usable 2D geometry, skipped: %1.</source>
        <translation>Entités sans géométrie 2D utilisable, ignorées : %1.</translation>
    </message>
    <message>
        <source>Open lines on layer “%1” that close into no outline, left out: %2 (%3 m); a larger “Close gaps up to” may close them.</source>
        <translation>Lignes ouvertes du calque « %1 » qui ne forment aucun contour, écartées : %2 (%3 m) ; une valeur plus grande de « Fermer les écarts jusqu’à » peut les fermer.</translation>
    </message>
    <message>
        <source>The model is larger than FloorCover imports.</source>
        <translation>La maquette dépasse ce que FloorCover importe.</translation>
    </message>
    <message>
        <source>FloorCover ran out of memory while reading the model: close other programs, or export a smaller part of the building.</source>
        <translation>FloorCover a manqué de mémoire en lisant la maquette : fermez d’autres programmes, ou exportez une plus petite partie du bâtiment.</translation>
    </message>
    <message>
        <source>FloorCover imports 3D building models as .ifc, .obj, .gltf, .glb or .stl files, not as “%1” files.</source>
        <translation>FloorCover importe les maquettes 3D de bâtiment en fichiers .ifc, .obj, .gltf, .glb ou .stl, pas en fichiers « %1 ».</translation>
    </message>
    <message>
        <source>The model cannot be read (%1): export it again from the modelling program.</source>
        <translation>La maquette ne peut pas être lue (%1) : exportez-la de nouveau depuis le logiciel de modélisation.</translation>
    </message>
    <message>
        <source>The model holds no 3D shapes (meshes) to cut: export it again with its geometry.</source>
        <translation>La maquette ne contient aucune forme 3D (maillage) à couper : exportez-la de nouveau avec sa géométrie.</translation>
    </message>
    <message>
        <source>The model holds no surfaces (triangles) to cut: export it again with its geometry.</source>
        <translation>La maquette ne contient aucune surface (triangles) à couper : exportez-la de nouveau avec sa géométrie.</translation>
    </message>
    <message>
        <source>The model has more than %1 triangles, more than FloorCover imports: export only the storey you need.</source>
        <translation>La maquette a plus de %1 triangles, plus que ce que FloorCover importe : exportez seulement l’étage dont vous avez besoin.</translation>
    </message>
    <message>
        <source>The model&apos;s parts are nested more than %1 levels deep, more than FloorCover imports.</source>
        <translation>Les parties de la maquette sont imbriquées sur plus de %1 niveaux, plus que ce que FloorCover importe.</translation>
    </message>
    <message>
        <source>The model is damaged (its part “%1” refers to geometry that is missing): export it again.</source>
        <translation>La maquette est endommagée (sa partie « %1 » renvoie à une géométrie manquante) : exportez-la de nouveau.</translation>
    </message>
    <message>
        <source>The model&apos;s part “%1” has an invalid or huge coordinate: check the Unit in the Import 3D Building Model dialog.</source>
        <translation>La partie « %1 » de la maquette a une coordonnée invalide ou énorme : vérifiez Unité dans la boîte de dialogue Importer une maquette 3D de bâtiment.</translation>
    </message>
    <message>
        <source>The unit must be a positive number of metres: choose another Unit in the Import 3D Building Model dialog.</source>
        <translation>L’unité doit être un nombre positif de mètres : choisissez une autre Unité dans la boîte de dialogue Importer une maquette 3D de bâtiment.</translation>
    </message>
    <message>
        <source>“Cut above the floor” must be a positive number of metres.</source>
        <translation>« Coupe au-dessus du sol » doit être un nombre positif de mètres.</translation>
    </message>
    <message>
        <source>The model has no storey “%1” (its storeys: %2): choose one under Storey.</source>
        <translation>La maquette n’a pas d’étage « %1 » (ses étages : %2) : choisissez-en un sous Étage.</translation>
    </message>
    <message>
        <source>The cut at height %1 (%3 above the floor of storey “%2”) meets no wall: lower “Cut above the floor”, or check the Unit and the Storey.</source>
        <translation>La coupe à la hauteur %1 (%3 au-dessus du sol de l’étage « %2 ») ne rencontre aucun mur : abaissez « Coupe au-dessus du sol », ou vérifiez l’Unité et l’Étage.</translation>
    </message>
    <message>
        <source>The cut at height %1 (%3 above the floor of storey “%2”) has more than %4 wall edges, more than FloorCover imports: try another “Cut above the floor”.</source>
        <translation>La coupe à la hauteur %1 (%3 au-dessus du sol de l’étage « %2 ») a plus de %4 arêtes de mur, plus que ce que FloorCover importe : essayez une autre « Coupe au-dessus du sol ».</translation>
    </message>
    <message>
        <source>The cut at height %1 (%3 above the floor of storey “%2”) encloses no free space: the outer walls are open at that height, or the model is not closed. Try another “Cut above the floor”.</source>
        <translation>La coupe à la hauteur %1 (%3 au-dessus du sol de l’étage « %2 ») n’enclôt aucun espace libre : les murs extérieurs sont ouverts à cette hauteur, ou la maquette n’est pas fermée. Essayez une autre « Coupe au-dessus du sol ».</translation>
    </message>
    <message>
        <source>The cut at height %1 (%3 above the floor of storey “%2”) makes no valid plan: %4</source>
        <translation>La coupe à la hauteur %1 (%3 au-dessus du sol de l’étage « %2 ») ne donne pas de plan valide : %4</translation>
    </message>
    <message>
        <source>Smaller enclosed areas apart from the main floor, left out: %1 (%2 m² in all).</source>
        <translation>Surfaces fermées plus petites que le sol principal, écartées : %1 (%2 m² en tout).</translation>
    </message>
    <message>
        <source>Space “%1” has no closed outline at the cut height and is left out as a room.</source>
        <translation>L’espace « %1 » n’a pas de contour fermé à la hauteur de coupe et n’est pas repris comme pièce.</translation>
    </message>
    <message>
        <source>Room “%1” is left out: %2</source>
        <translation>La pièce « %1 » est écartée : %2</translation>
    </message>
    <message>
        <source>The map&apos;s rooms could not be separated: choose One room under “Split into rooms”, or another way to split.</source>
        <translation>Les pièces de la carte n’ont pas pu être séparées : choisissez Une seule pièce sous « Diviser en pièces », ou une autre division.</translation>
    </message>
    <message>
        <source>A speed of %1 m/s is not plausible for a robot (0.001 to 100 m/s): change it in the Planning panel.</source>
        <translation>Une vitesse de %1 m/s n’est pas plausible pour un robot (de 0,001 à 100 m/s) : modifiez-la dans le panneau Planification.</translation>
    </message>
    <message>
        <source>A turn time of %1 s is not plausible (at most an hour per turn): change it in the Planning panel.</source>
        <translation>Un temps de virage de %1 s n’est pas plausible (au plus une heure par virage) : modifiez-le dans le panneau Planification.</translation>
    </message>
    <message>
        <source>%1: vertex %3 has a coordinate of %2 m, beyond the range of any map projection: is the plan in metres?</source>
        <translation>%1 : le sommet %3 a une coordonnée de %2 m, hors de la portée de toute projection cartographique : le plan est-il en mètres ?</translation>
    </message>
    <message>
        <source>The boundary spans %1 km, more than the %2 km of any site on Earth: is the plan in metres?</source>
        <translation>Le contour s’étend sur %1 km, plus que les %2 km de tout site sur Terre : le plan est-il en mètres ?</translation>
    </message>
    <message>
        <source>The unit must be a positive number of metres below 1,000,000 (0.001 for a drawing in millimetres): correct Units in the import dialog.</source>
        <translation>L’unité doit être un nombre positif de mètres inférieur à 1 000 000 (0,001 pour un dessin en millimètres) : corrigez Unité dans la boîte de dialogue d’importation.</translation>
    </message>
    <message>
        <source>The file names EPSG code %1, which is not valid (codes run from 1 to %2).</source>
        <translation>Le fichier indique le code EPSG %1, qui n’est pas valide (les codes vont de 1 à %2).</translation>
    </message>
    <message>
        <source>The point (%1, %2) in EPSG:%3 is not on the globe: are the coordinates in that system?</source>
        <translation>Le point (%1, %2) en EPSG:%3 n’est pas sur le globe : les coordonnées sont-elles dans ce système ?</translation>
    </message>
    <message>
        <source>The file is not JSON text (it holds a zero byte at offset %1): is it a binary file?</source>
        <translation>Le fichier n’est pas du texte JSON (il contient un octet nul à la position %1) : est-ce un fichier binaire ?</translation>
    </message>
    <message>
        <source>“Fill notches up to” must be at most %1 m, not %2 m.</source>
        <translation>« Combler les encoches jusqu&apos;à » doit valoir au plus %1 m, pas %2 m.</translation>
    </message>
    <message>
        <source>“Remove obstacles up to” must be at most %1 m, not %2 m.</source>
        <translation>« Supprimer les obstacles jusqu&apos;à » doit valoir au plus %1 m, pas %2 m.</translation>
    </message>
    <message>
        <source>The floor would need about %1 tiles of a %2 m block leg, more than %3: choose a longer block leg.</source>
        <translation>La surface demanderait environ %1 tuiles pour un côté de bloc de %2 m, plus que %3 : choisissez un côté de bloc plus long.</translation>
    </message>
    <message>
        <source>The block masses must be positive, at most 1,000,000 kg: change them in the Tiling Robot panel.</source>
        <translation>Les masses des blocs doivent être positives, au plus 1 000 000 kg : modifiez-les dans le panneau Robot à pavage.</translation>
    </message>
    <message>
        <source>Obstacles that touched the outer wall or each other at a single point were shrunk by 1 mm.</source>
        <translation>Les obstacles qui touchaient le mur extérieur ou un autre obstacle en un seul point ont été réduits de 1 mm.</translation>
    </message>
</context>
<context>
    <name>fc::ui</name>
    <message>
        <source>Office floor</source>
        <translation>Étage de bureaux</translation>
    </message>
    <message>
        <source>Twelve offices along a corridor</source>
        <translation>Douze bureaux le long d’un couloir</translation>
    </message>
    <message>
        <source>Hospital ward</source>
        <translation>Service hospitalier</translation>
    </message>
    <message>
        <source>Sixteen patient rooms with beds and a corridor</source>
        <translation>Seize chambres de patients avec lits et un couloir</translation>
    </message>
    <message>
        <source>Room with a pillar</source>
        <translation>Pièce avec un pilier</translation>
    </message>
    <message>
        <source>One room with an obstacle in it</source>
        <translation>Une pièce avec un obstacle à l’intérieur</translation>
    </message>
    <message>
        <source>Room with notches</source>
        <translation>Pièce avec renfoncements</translation>
    </message>
    <message>
        <source>One room whose walls have recesses</source>
        <translation>Une pièce dont les murs ont des renfoncements</translation>
    </message>
    <message>
        <source>Slanted room</source>
        <translation>Pièce en biais</translation>
    </message>
    <message>
        <source>A room drawn at an angle, with an obstacle</source>
        <translation>Une pièce dessinée en biais, avec un obstacle</translation>
    </message>
    <message>
        <source>Simple room</source>
        <translation>Pièce simple</translation>
    </message>
    <message>
        <source>The smallest example: one room, one obstacle</source>
        <translation>Le plus petit exemple : une pièce, un obstacle</translation>
    </message>
</context>
<context>
    <name>fc::ui::BuildingImportDialog</name>
    <message>
        <source>File&apos;s unit</source>
        <translation>Unité du fichier</translation>
    </message>
    <message>
        <source>Metres</source>
        <translation>Mètres</translation>
    </message>
    <message>
        <source>Centimetres</source>
        <translation>Centimètres</translation>
    </message>
    <message>
        <source>Millimetres</source>
        <translation>Millimètres</translation>
    </message>
    <message>
        <source>Feet</source>
        <translation>Pieds</translation>
    </message>
    <message>
        <source>Inches</source>
        <translation>Pouces</translation>
    </message>
    <message>
        <source>Door leaves do not block</source>
        <translation>Les vantaux de porte ne bloquent pas</translation>
    </message>
    <message>
        <source>Import 3D Building Model — %1</source>
        <translation>Importer une maquette 3D de bâtiment — %1</translation>
    </message>
    <message>
        <source> m</source>
        <translation> m</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>Automatique</translation>
    </message>
    <message>
        <source>Y up</source>
        <translation>Y vers le haut</translation>
    </message>
    <message>
        <source>Z up</source>
        <translation>Z vers le haut</translation>
    </message>
    <message>
        <source>Storey:</source>
        <translation>Étage :</translation>
    </message>
    <message>
        <source>Cut above the floor:</source>
        <translation>Coupe au-dessus du sol :</translation>
    </message>
    <message>
        <source>Unit:</source>
        <translation>Unité :</translation>
    </message>
    <message>
        <source>Up axis:</source>
        <translation>Axe vertical :</translation>
    </message>
    <message>
        <source>%1 obstacles, %2 rooms</source>
        <translation>%1 obstacles, %2 pièces</translation>
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
        <translation>Planification avec chaque solveur…</translation>
    </message>
    <message>
        <source>Compare Solvers</source>
        <translation>Comparer les solveurs</translation>
    </message>
    <message>
        <source>Solver</source>
        <translation>Solveur</translation>
    </message>
    <message>
        <source>Length (m)</source>
        <translation>Longueur (m)</translation>
    </message>
    <message>
        <source>Extra (m)</source>
        <translation>Supplément (m)</translation>
    </message>
    <message>
        <source>Turns</source>
        <translation>Virages</translation>
    </message>
    <message>
        <source>Coverage</source>
        <translation>Couverture</translation>
    </message>
    <message>
        <source>Time (s)</source>
        <translation>Durée (s)</translation>
    </message>
    <message>
        <source>Planning (s)</source>
        <translation>Planification (s)</translation>
    </message>
    <message>
        <source>%1 of %2 solvers answered; overlaps are drawn in blue.</source>
        <translation>%1 solveurs sur %2 ont répondu ; les recouvrements sont tracés en bleu.</translation>
    </message>
    <message>
        <source>Comparing the solvers</source>
        <translation>Comparaison des solveurs</translation>
    </message>
    <message>
        <source>Planning with every solver… (%1)</source>
        <translation>Planification avec chaque solveur… (%1)</translation>
    </message>
    <message>
        <source>The comparison failed: %1</source>
        <translation>La comparaison a échoué : %1</translation>
    </message>
    <message>
        <source>The comparison was cancelled.</source>
        <translation>La comparaison a été annulée.</translation>
    </message>
    <message>
        <source>The method that ordered the rooms&apos; cells</source>
        <translation>La méthode qui a ordonné les cellules des pièces</translation>
    </message>
    <message>
        <source>How far the robot drives in all</source>
        <translation>La distance totale parcourue par le robot</translation>
    </message>
    <message>
        <source>Distance beyond the stripes themselves (floor area / coverage width): the moves between stripes and rooms. Less is better.</source>
        <translation>Distance au-delà des bandes elles-mêmes (surface / largeur de couverture) : les trajets entre bandes et pièces. Moins, c’est mieux.</translation>
    </message>
    <message>
        <source>Turns the robot makes; each costs the turn time</source>
        <translation>Virages du robot ; chacun coûte le temps de virage</translation>
    </message>
    <message>
        <source>Share of the floor the robot can reach that the path sweeps</source>
        <translation>Part du sol accessible que le chemin balaie</translation>
    </message>
    <message>
        <source>Estimated cleaning time: length / speed + turns × turn time</source>
        <translation>Temps de nettoyage estimé : longueur / vitesse + virages × temps de virage</translation>
    </message>
    <message>
        <source>How long the computer took to plan</source>
        <translation>Le temps de calcul de la planification</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Arrêter</translation>
    </message>
    <message>
        <source>Stop comparing; solvers that answered stay in the table</source>
        <translation>Arrêter la comparaison ; les solveurs qui ont répondu restent dans le tableau</translation>
    </message>
    <message>
        <source>Did not plan: %1</source>
        <translation>Pas de plan : %1</translation>
    </message>
    <message>
        <source>%1 drives %3 % of the extra distance of %2 (a published method) and makes %4 % of its turns; below 100 % is better. The published comparison: %5.</source>
        <translation>%1 parcourt %3 % de la distance supplémentaire de %2 (une méthode publiée) et fait %4 % de ses virages ; moins de 100 %, c’est mieux. La comparaison publiée : %5.</translation>
    </message>
    <message>
        <source>Close; a comparison still running is cancelled at once</source>
        <translation>Fermer ; une comparaison encore en cours est annulée aussitôt</translation>
    </message>
    <message>
        <source>One row per solver; hover a column&apos;s title for what it means.</source>
        <translation>Une ligne par solveur ; survolez le titre d’une colonne pour voir ce qu’il signifie.</translation>
    </message>
</context>
<context>
    <name>fc::ui::Document</name>
    <message>
        <source>Untitled</source>
        <translation>Sans titre</translation>
    </message>
    <message>
        <source>Draw the boundary first: obstacles and rooms must lie inside it.</source>
        <translation>Dessinez d’abord le contour : les obstacles et les pièces doivent se trouver à l’intérieur.</translation>
    </message>
    <message>
        <source>Room %1</source>
        <translation>Pièce %1</translation>
    </message>
    <message>
        <source>Add boundary</source>
        <translation>Ajouter le contour</translation>
    </message>
    <message>
        <source>Replace boundary</source>
        <translation>Remplacer le contour</translation>
    </message>
    <message>
        <source>Add obstacle</source>
        <translation>Ajouter un obstacle</translation>
    </message>
    <message>
        <source>Add room %1</source>
        <translation>Ajouter la pièce %1</translation>
    </message>
    <message>
        <source>Move vertex</source>
        <translation>Déplacer le sommet</translation>
    </message>
    <message>
        <source>Insert vertex</source>
        <translation>Insérer un sommet</translation>
    </message>
    <message>
        <source>A polygon needs at least three vertices; delete the polygon instead.</source>
        <translation>Un polygone a besoin d’au moins trois sommets ; supprimez plutôt le polygone.</translation>
    </message>
    <message>
        <source>Delete vertex</source>
        <translation>Supprimer le sommet</translation>
    </message>
    <message>
        <source>Delete the obstacles and rooms before the boundary.</source>
        <translation>Supprimez les obstacles et les pièces avant le contour.</translation>
    </message>
    <message>
        <source>Delete boundary</source>
        <translation>Supprimer le contour</translation>
    </message>
    <message>
        <source>Delete obstacle</source>
        <translation>Supprimer l’obstacle</translation>
    </message>
    <message>
        <source>Delete room %1</source>
        <translation>Supprimer la pièce %1</translation>
    </message>
    <message>
        <source>There is no room %1.</source>
        <translation>Il n’y a pas de pièce %1.</translation>
    </message>
    <message>
        <source>A room needs a name.</source>
        <translation>Une pièce a besoin d’un nom.</translation>
    </message>
    <message>
        <source>There is already a room named &quot;%1&quot;.</source>
        <translation>Il existe déjà une pièce nommée « %1 ».</translation>
    </message>
    <message>
        <source>Rename room %1 to %2</source>
        <translation>Renommer la pièce %1 en %2</translation>
    </message>
    <message>
        <source>Change robot profile</source>
        <translation>Modifier le profil du robot</translation>
    </message>
    <message>
        <source>The sweep angle must be a finite number of degrees.</source>
        <translation>L’angle de balayage doit être un nombre fini de degrés.</translation>
    </message>
    <message>
        <source>Change sweep angle</source>
        <translation>Modifier l’angle de balayage</translation>
    </message>
    <message>
        <source>Choose solver %1</source>
        <translation>Choisir le solveur %1</translation>
    </message>
    <message>
        <source>Place start</source>
        <translation>Placer le départ</translation>
    </message>
    <message>
        <source>Remove start</source>
        <translation>Retirer le départ</translation>
    </message>
    <message>
        <source>Place end</source>
        <translation>Placer l’arrivée</translation>
    </message>
    <message>
        <source>Remove end</source>
        <translation>Retirer l’arrivée</translation>
    </message>
    <message>
        <source>There is no room named &quot;%1&quot;.</source>
        <translation>Il n’y a pas de pièce nommée « %1 ».</translation>
    </message>
    <message>
        <source>At least one room must stay selected for planning.</source>
        <translation>Au moins une pièce doit rester sélectionnée pour la planification.</translation>
    </message>
    <message>
        <source>Deselect room %1</source>
        <translation>Désélectionner la pièce %1</translation>
    </message>
    <message>
        <source>Select room %1</source>
        <translation>Sélectionner la pièce %1</translation>
    </message>
    <message>
        <source>There is no such polygon.</source>
        <translation>Ce polygone n’existe pas.</translation>
    </message>
    <message>
        <source>There is no such vertex.</source>
        <translation>Ce sommet n’existe pas.</translation>
    </message>
    <message>
        <source>Choose two different rooms to merge.</source>
        <translation>Choisissez deux pièces différentes à fusionner.</translation>
    </message>
    <message>
        <source>%1 and %2 cannot be merged: %3</source>
        <translation>%1 et %2 ne peuvent pas être fusionnées : %3</translation>
    </message>
    <message>
        <source>Merge rooms %1 and %2</source>
        <translation>Fusionner les pièces %1 et %2</translation>
    </message>
    <message>
        <source>%1 cannot be split: %2</source>
        <translation>%1 ne peut pas être divisée : %2</translation>
    </message>
    <message>
        <source>Split room %1 (new room %2)</source>
        <translation>Diviser la pièce %1 (nouvelle pièce %2)</translation>
    </message>
    <message>
        <source>The plan cannot be repaired automatically: %1</source>
        <translation>Le plan ne peut pas être réparé automatiquement : %1</translation>
    </message>
    <message>
        <source>The automatic repair left a problem: %1</source>
        <translation>La réparation automatique a laissé un problème : %1</translation>
    </message>
    <message>
        <source>Repair plan</source>
        <translation>Réparer le plan</translation>
    </message>
    <message>
        <source>This plan has problems (see the Problems panel): repair it first with Plan &gt; Repair Plan, or undo back to a valid plan.</source>
        <translation>Ce plan a des problèmes (voir le panneau Problèmes) : réparez-le d’abord avec Planifier &gt; Réparer le plan, ou annulez jusqu’à revenir à un plan valide.</translation>
    </message>
</context>
<context>
    <name>fc::ui::DocumentFiles</name>
    <message>
        <source>Cannot save %1: %2</source>
        <translation>Impossible d’enregistrer %1 : %2</translation>
    </message>
</context>
<context>
    <name>fc::ui::DrawPolygonTool</name>
    <message>
        <source>Draw Boundary</source>
        <translation>Dessiner le contour</translation>
    </message>
    <message>
        <source>Draw Obstacle</source>
        <translation>Dessiner un obstacle</translation>
    </message>
    <message>
        <source>Draw Room</source>
        <translation>Dessiner une pièce</translation>
    </message>
    <message>
        <source>%1: click vertices and click the first one to close, or drag a rectangle. Shift keeps right angles, Backspace removes a vertex, Esc cancels.</source>
        <translation>%1 : cliquez les sommets puis de nouveau le premier pour fermer, ou tracez un rectangle. Maj garde les angles droits, Retour arrière retire un sommet, Échap annule.</translation>
    </message>
    <message>
        <source>A polygon needs at least three vertices.</source>
        <translation>Un polygone a besoin d’au moins trois sommets.</translation>
    </message>
    <message>
        <source>%1 refused: %2</source>
        <translation>%1 refusé : %2</translation>
    </message>
    <message>
        <source>Kept the existing boundary.</source>
        <translation>La limite existante est conservée.</translation>
    </message>
    <message>
        <source>The plan already has a boundary, and a plan has only one. Replace it with the one you drew? (Undo brings the old boundary back.)</source>
        <translation>Le plan a déjà une limite, et un plan n’en a qu’une. La remplacer par celle que vous avez dessinée ? (Annuler rétablit l’ancienne limite.)</translation>
    </message>
</context>
<context>
    <name>fc::ui::EditVerticesTool</name>
    <message>
        <source>Edit Vertices</source>
        <translation>Modifier les sommets</translation>
    </message>
    <message>
        <source>Edit Vertices: drag a vertex to move it, double-click an edge to add one, right-click a vertex to delete it; select a polygon and press Delete to delete it.</source>
        <translation>Modifier les sommets : faites glisser un sommet pour le déplacer, double-cliquez une arête pour en ajouter un, clic droit sur un sommet pour le supprimer ; sélectionnez un polygone et appuyez sur Suppr pour le supprimer.</translation>
    </message>
</context>
<context>
    <name>fc::ui::HelpDialog</name>
    <message>
        <source>Getting Started with FloorCover</source>
        <translation>Premiers pas avec FloorCover</translation>
    </message>
    <message>
        <source>Close the guide</source>
        <translation>Fermer le guide</translation>
    </message>
</context>
<context>
    <name>fc::ui::ImportDialog</name>
    <message>
        <source>Boundary</source>
        <translation>Contour</translation>
    </message>
    <message>
        <source>Obstacles</source>
        <translation>Obstacles</translation>
    </message>
    <message>
        <source>Rooms</source>
        <translation>Pièces</translation>
    </message>
    <message>
        <source>Ignored</source>
        <translation>Ignoré</translation>
    </message>
    <message>
        <source>Auto (by shape)</source>
        <translation>Automatique (selon la forme)</translation>
    </message>
    <message>
        <source>Open as a new document</source>
        <translation>Ouvrir comme nouveau document</translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation>Importer %1</translation>
    </message>
    <message>
        <source>Layer</source>
        <translation>Calque</translation>
    </message>
    <message>
        <source>Role</source>
        <translation>Rôle</translation>
    </message>
    <message>
        <source> m per unit</source>
        <translation> m par unité</translation>
    </message>
    <message>
        <source> m</source>
        <translation> m</translation>
    </message>
    <message>
        <source>Units:</source>
        <translation>Unité :</translation>
    </message>
    <message>
        <source>Close gaps up to:</source>
        <translation>Fermer les écarts jusqu’à :</translation>
    </message>
    <message>
        <source>Free area %1 m², %2 obstacles, %3 rooms</source>
        <translation>Surface libre %1 m², %2 obstacles, %3 pièces</translation>
    </message>
    <message>
        <source>Clean the map</source>
        <translation>Nettoyer la carte</translation>
    </message>
    <message>
        <source>Walls</source>
        <translation>Murs</translation>
    </message>
    <message>
        <source>Floor</source>
        <translation>Sol</translation>
    </message>
    <message>
        <source> m²</source>
        <translation> m²</translation>
    </message>
    <message>
        <source>Obstacle specks smaller than this become floor (sensor noise)</source>
        <translation>Les taches d&apos;obstacle plus petites deviennent du sol (bruit du capteur)</translation>
    </message>
    <message>
        <source>Free islands smaller than this are dropped</source>
        <translation>Les îlots libres plus petits sont écartés</translation>
    </message>
    <message>
        <source>Notches and slivers narrower than twice this are filled (the robot&apos;s radius: what its body cannot enter)</source>
        <translation>Les encoches et fentes plus étroites que le double sont comblées (le rayon du robot : là où son corps n&apos;entre pas)</translation>
    </message>
    <message>
        <source>Obstacles thinner than twice this vanish (0: off; thin walls too)</source>
        <translation>Les obstacles plus fins que le double disparaissent (0 : désactivé ; les murs fins aussi)</translation>
    </message>
    <message>
        <source>Along the map&apos;s two main directions</source>
        <translation>Selon les deux directions principales de la carte</translation>
    </message>
    <message>
        <source>Each ragged wall becomes one line within a cell of its scan, so the path runs along it instead of zigzagging</source>
        <translation>Chaque mur irrégulier devient une ligne à une cellule près de son relevé, pour que le trajet le longe au lieu de zigzaguer</translation>
    </message>
    <message>
        <source>Notches in a straightened wall up to this deep are filled</source>
        <translation>Les encoches d&apos;un mur redressé jusqu&apos;à cette profondeur sont comblées</translation>
    </message>
    <message>
        <source>At doorways (distance)</source>
        <translation>Aux portes (distance)</translation>
    </message>
    <message>
        <source>At doorways (morphological)</source>
        <translation>Aux portes (morphologique)</translation>
    </message>
    <message>
        <source>One room</source>
        <translation>Une seule pièce</translation>
    </message>
    <message>
        <source>Smaller rooms (alcoves, door recesses) join a neighbour</source>
        <translation>Les pièces plus petites (alcôves, embrasures) rejoignent une voisine</translation>
    </message>
    <message>
        <source>Unknown cells are:</source>
        <translation>Les cellules inconnues sont :</translation>
    </message>
    <message>
        <source>Remove specks below:</source>
        <translation>Supprimer les taches sous :</translation>
    </message>
    <message>
        <source>Drop islands below:</source>
        <translation>Écarter les îlots sous :</translation>
    </message>
    <message>
        <source>Fill notches up to:</source>
        <translation>Combler les encoches jusqu&apos;à :</translation>
    </message>
    <message>
        <source>Remove obstacles up to:</source>
        <translation>Supprimer les obstacles jusqu&apos;à :</translation>
    </message>
    <message>
        <source>Straighten walls:</source>
        <translation>Redresser les murs :</translation>
    </message>
    <message>
        <source>Fill notches in straight walls up to:</source>
        <translation>Combler les encoches des murs droits jusqu&apos;à :</translation>
    </message>
    <message>
        <source>Split into rooms:</source>
        <translation>Diviser en pièces :</translation>
    </message>
    <message>
        <source>Smallest room:</source>
        <translation>Plus petite pièce :</translation>
    </message>
    <message>
        <source>Cleaning removed %1 specks (%2 m²) and %3 free islands (%4 m²); filling notches took %5 m², removing thin obstacles gave %6 m².</source>
        <translation>Le nettoyage a supprimé %1 taches (%2 m²) et %3 îlots libres (%4 m²) ; combler les encoches a pris %5 m², supprimer les obstacles fins a rendu %6 m².</translation>
    </message>
    <message>
        <source>%1 walls straightened at %2°: %3 m² of floor gained, %4 m² lost (%5 notches filled); %6 unknown gaps became floor.</source>
        <translation>%1 murs redressés à %2° : %3 m² de sol gagnés, %4 m² perdus (%5 encoches comblées) ; %6 lacunes inconnues sont devenues du sol.</translation>
    </message>
    <message>
        <source>The drawing&apos;s layers: choose what each holds (walls, obstacles, rooms, or nothing to import).</source>
        <translation>Les calques du dessin : choisissez ce que contient chacun (murs, obstacles, pièces, ou rien à importer).</translation>
    </message>
    <message>
        <source>How many metres one drawing unit is (0.001 for a drawing in mm).</source>
        <translation>Combien de mètres vaut une unité du dessin (0,001 pour un dessin en mm).</translation>
    </message>
    <message>
        <source>Lines whose ends are at most this far apart are joined into closed outlines.</source>
        <translation>Les lignes dont les extrémités sont au plus à cette distance sont reliées en contours fermés.</translation>
    </message>
    <message>
        <source>What the import left out or guessed, and why.</source>
        <translation>Ce que l’import a laissé de côté ou deviné, et pourquoi.</translation>
    </message>
    <message>
        <source>Open the import as its own document instead of replacing the plan of the current one.</source>
        <translation>Ouvrir l’import comme document séparé au lieu de remplacer le plan du document courant.</translation>
    </message>
    <message>
        <source>What the map&apos;s unknown (grey) cells are: walls, or floor the robot may clean.</source>
        <translation>Ce que sont les cellules inconnues (grises) de la carte : des murs, ou du sol que le robot peut nettoyer.</translation>
    </message>
    <message>
        <source>How the map&apos;s free space is split into rooms: at doorways (two methods), or kept as one room.</source>
        <translation>Comment l’espace libre de la carte est divisé en pièces : aux portes (deux méthodes), ou gardé en une seule pièce.</translation>
    </message>
    <message>
        <source>What layer %1 holds</source>
        <translation>Ce que contient le calque %1</translation>
    </message>
    <message numerus="yes">
        <source>Obstacles joined to their neighbours across gaps narrower than the robot: %n (%1 m²).</source>
        <translation>
            <numerusform>Obstacles reliés à leurs voisins par des passages plus étroits que le robot : %n (%1 m²).</numerusform>
            <numerusform>Obstacles reliés à leurs voisins par des passages plus étroits que le robot : %n (%1 m²).</numerusform>
        </translation>
    </message>
    <message>
        <source>Building:</source>
        <translation>Bâtiment :</translation>
    </message>
    <message>
        <source>The file holds several buildings (outer walls); a plan holds one. Largest first.</source>
        <translation>Le fichier contient plusieurs bâtiments (murs extérieurs) ; un plan en contient un. Le plus grand d’abord.</translation>
    </message>
    <message numerus="yes">
        <source>Doorway borders between rooms laid along the walls: %n.</source>
        <translation>
            <numerusform>Limites de porte entre pièces alignées sur les murs : %n.</numerusform>
            <numerusform>Limites de porte entre pièces alignées sur les murs : %n.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>fc::ui::LegendDock</name>
    <message>
        <source>Legend</source>
        <translation>Légende</translation>
    </message>
    <message>
        <source>Transit</source>
        <translation>Trajet à vide</translation>
    </message>
    <message>
        <source>Moves between cells and rooms without cleaning (part of the Path)</source>
        <translation>Déplacements entre cellules et pièces sans nettoyer (font partie du Trajet)</translation>
    </message>
    <message>
        <source>S</source>
        <translation>D</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Départ</translation>
    </message>
    <message>
        <source>Where the robot starts: yours, or the planner&apos;s choice when none is placed</source>
        <translation>Là où le robot part : votre départ, ou le choix du planificateur si aucun n’est placé</translation>
    </message>
    <message>
        <source>E</source>
        <translation>A</translation>
    </message>
    <message>
        <source>End</source>
        <translation>Arrivée</translation>
    </message>
    <message>
        <source>Where the path ends</source>
        <translation>Là où le trajet se termine</translation>
    </message>
</context>
<context>
    <name>fc::ui::MainWindow</name>
    <message>
        <source>Tools</source>
        <translation>Outils</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>É&amp;dition</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Annuler</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Rétablir</translation>
    </message>
    <message>
        <source>&amp;Preferences…</source>
        <translation>&amp;Préférences…</translation>
    </message>
    <message>
        <source>&amp;Tools</source>
        <translation>&amp;Outils</translation>
    </message>
    <message>
        <source>&amp;Plan</source>
        <translation>&amp;Planifier</translation>
    </message>
    <message>
        <source>&amp;Plan Path</source>
        <translation>&amp;Planifier le trajet</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Aide</translation>
    </message>
    <message>
        <source>&amp;About FloorCover</source>
        <translation>À &amp;propos de FloorCover</translation>
    </message>
    <message>
        <source>About FloorCover</source>
        <translation>À propos de FloorCover</translation>
    </message>
    <message>
        <source>FloorCover %1
Coverage path planning for cleaning and disinfection robots.</source>
        <translation>FloorCover %1
Planification de trajets de couverture pour robots de nettoyage et de désinfection.</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Affichage</translation>
    </message>
    <message>
        <source>&amp;Fit to Plan</source>
        <translation>&amp;Ajuster au plan</translation>
    </message>
    <message>
        <source>Zoom &amp;In</source>
        <translation>Zoom &amp;avant</translation>
    </message>
    <message>
        <source>Zoom &amp;Out</source>
        <translation>Zoom a&amp;rrière</translation>
    </message>
    <message>
        <source>Show &amp;Grid</source>
        <translation>Afficher la &amp;grille</translation>
    </message>
    <message>
        <source>Snap to G&amp;rid</source>
        <translation>Aimanter à la g&amp;rille</translation>
    </message>
    <message>
        <source>Snap to &amp;Vertices</source>
        <translation>Aimanter aux &amp;sommets</translation>
    </message>
    <message>
        <source>&amp;Overlays</source>
        <translation>&amp;Calques</translation>
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
        <translation>Modifications non enregistrées</translation>
    </message>
    <message>
        <source>%1 has unsaved changes. Save them?</source>
        <translation>%1 a des modifications non enregistrées. Les enregistrer ?</translation>
    </message>
    <message>
        <source>Recover unsaved changes</source>
        <translation>Récupérer les modifications non enregistrées</translation>
    </message>
    <message>
        <source>Recovered the unsaved changes of the last session.</source>
        <translation>Les modifications non enregistrées de la dernière session ont été récupérées.</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>%1 ouvert</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Fichier</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>&amp;Nouveau</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>&amp;Ouvrir…</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>Fichiers &amp;récents</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Enregistrer</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>Enregistrer &amp;sous…</translation>
    </message>
    <message>
        <source>&amp;Export Path…</source>
        <translation>E&amp;xporter le trajet…</translation>
    </message>
    <message>
        <source>Export View as &amp;PNG…</source>
        <translation>Exporter la vue en &amp;PNG…</translation>
    </message>
    <message>
        <source>Export View as S&amp;VG…</source>
        <translation>Exporter la vue en S&amp;VG…</translation>
    </message>
    <message>
        <source>Export &amp;Report as PDF…</source>
        <translation>Exporter le &amp;rapport en PDF…</translation>
    </message>
    <message>
        <source>Export Report</source>
        <translation>Exporter le rapport</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Quitter</translation>
    </message>
    <message>
        <source>Open Plan</source>
        <translation>Ouvrir un plan</translation>
    </message>
    <message>
        <source>Plans and projects (*.fcproj *.geojson *.json);;FloorCover projects (*.fcproj);;GeoJSON plans (*.geojson *.json)</source>
        <translation>Plans et projets (*.fcproj *.geojson *.json);;Projets FloorCover (*.fcproj);;Plans GeoJSON (*.geojson *.json)</translation>
    </message>
    <message>
        <source>Save Project</source>
        <translation>Enregistrer le projet</translation>
    </message>
    <message>
        <source>FloorCover projects (*.fcproj)</source>
        <translation>Projets FloorCover (*.fcproj)</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 enregistré</translation>
    </message>
    <message>
        <source>There is no path to export: plan the current document first.</source>
        <translation>Aucun trajet à exporter : planifiez d’abord le document courant.</translation>
    </message>
    <message>
        <source>Floor plan exported by FloorCover</source>
        <translation>Plan exporté par FloorCover</translation>
    </message>
    <message>
        <source>Cannot write %1.</source>
        <translation>Impossible d’écrire %1.</translation>
    </message>
    <message>
        <source>Exported the view to %1</source>
        <translation>Vue exportée vers %1</translation>
    </message>
    <message>
        <source>SVG images (*.svg)</source>
        <translation>Images SVG (*.svg)</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>Images PNG (*.png)</translation>
    </message>
    <message>
        <source>Export View</source>
        <translation>Exporter la vue</translation>
    </message>
    <message>
        <source>There is no plan to report: plan the current document first.</source>
        <translation>Aucune planification pour le rapport : planifiez d’abord le document courant.</translation>
    </message>
    <message>
        <source>Exported the report to %1</source>
        <translation>Rapport exporté vers %1</translation>
    </message>
    <message>
        <source>planning failed: %1</source>
        <translation>échec de la planification : %1</translation>
    </message>
    <message>
        <source>cannot write %1</source>
        <translation>impossible d’écrire %1</translation>
    </message>
    <message>
        <source>History</source>
        <translation>Historique</translation>
    </message>
    <message>
        <source>&amp;Compare Solvers…</source>
        <translation>&amp;Comparer les solveurs…</translation>
    </message>
    <message>
        <source>&amp;Import…</source>
        <translation>&amp;Importer…</translation>
    </message>
    <message>
        <source>Import Plan</source>
        <translation>Importer un plan</translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation>Importer %1</translation>
    </message>
    <message numerus="yes">
        <source>Imported %1 (%n warning(s))</source>
        <translation>
            <numerusform>%1 importé (%n avertissement)</numerusform>
            <numerusform>%1 importé (%n avertissements)</numerusform>
        </translation>
    </message>
    <message>
        <source>Cannot export the path to %1: unknown file extension</source>
        <translation>Impossible d’exporter le trajet vers %1 : extension de fichier inconnue</translation>
    </message>
    <message>
        <source>Cannot export to %1: %2</source>
        <translation>Impossible d’exporter vers %1 : %2</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exporter</translation>
    </message>
    <message>
        <source>Export &amp;Zones…</source>
        <translation>Exporter les &amp;zones…</translation>
    </message>
    <message>
        <source>Export P&amp;lan (WGS84 GeoJSON, WKT)…</source>
        <translation>Exporter le p&amp;lan (GeoJSON WGS84, WKT)…</translation>
    </message>
    <message>
        <source>Importable plans (%1);;DXF drawings (*.dxf);;ROS occupancy maps (*.yaml *.yml);;WKT polygons (*.wkt);;GeoJSON plans (*.geojson *.json);;3D building models (*.ifc *.obj *.gltf *.glb *.stl)</source>
        <translation>Plans importables (%1);;Dessins DXF (*.dxf);;Cartes d’occupation ROS (*.yaml *.yml);;Polygones WKT (*.wkt);;Plans GeoJSON (*.geojson *.json);;Maquettes 3D de bâtiment (*.ifc *.obj *.gltf *.glb *.stl)</translation>
    </message>
    <message>
        <source>an untitled plan</source>
        <translation>un plan sans titre</translation>
    </message>
    <message>
        <source>%1 (in %2)</source>
        <translation>%1 (dans %2)</translation>
    </message>
    <message>
        <source>FloorCover did not close normally last time. Recover the unsaved changes to %1, saved automatically %2?</source>
        <translation>FloorCover ne s’est pas fermé normalement la dernière fois. Récupérer les modifications non enregistrées de %1, sauvegardées automatiquement le %2 ?</translation>
    </message>
    <message>
        <source>Exported %1 to %2 (%3)</source>
        <translation>%1 exporté vers %2 (%3)</translation>
    </message>
    <message>
        <source>Exported the path as %1 to
%2</source>
        <translation>Le chemin a été exporté en %1 vers
%2</translation>
    </message>
    <message>
        <source>Exported the zones as %1 to
%2</source>
        <translation>Les zones ont été exportées en %1 vers
%2</translation>
    </message>
    <message>
        <source>Exported the plan as %1 to
%2</source>
        <translation>Le plan a été exporté en %1 vers
%2</translation>
    </message>
    <message>
        <source>Show in Folder</source>
        <translation>Afficher dans le dossier</translation>
    </message>
    <message>
        <source>&amp;Replan After Each Edit</source>
        <translation>&amp;Replanifier après chaque modification</translation>
    </message>
    <message>
        <source>Plan the path again in the background whenever the floor, the rooms or the start and end change; the old path stays greyed until then.</source>
        <translation>Replanifier le trajet en arrière-plan dès que le plan, les pièces, le départ ou l’arrivée changent ; l’ancien trajet reste grisé jusque-là.</translation>
    </message>
    <message>
        <source>Loaded the trained model %1</source>
        <translation>Modèle entraîné %1 chargé</translation>
    </message>
    <message>
        <source>The trained model beside the project was not loaded (%1): %2</source>
        <translation>Le modèle entraîné à côté du projet n’a pas été chargé (%1) : %2</translation>
    </message>
    <message>
        <source>The project was saved, but not its trained model: %1</source>
        <translation>Le projet a été enregistré, mais pas son modèle entraîné : %1</translation>
    </message>
    <message>
        <source>&amp;Path View</source>
        <translation>Vue &amp;Trajet</translation>
    </message>
    <message>
        <source>The floor, the rooms and the path with its start and end</source>
        <translation>Le sol, les pièces et le trajet avec son départ et son arrivée</translation>
    </message>
    <message>
        <source>&amp;Graph View</source>
        <translation>Vue Gra&amp;phe</translation>
    </message>
    <message>
        <source>Adds the planner&apos;s cells, corners and graph edges</source>
        <translation>Ajoute les cellules, les coins et les arêtes du graphe du planificateur</translation>
    </message>
    <message>
        <source>Open &amp;Sample</source>
        <translation>Ouvrir un exe&amp;mple</translation>
    </message>
    <message>
        <source>PDF report, A4 (*.pdf)</source>
        <translation>Rapport PDF, A4 (*.pdf)</translation>
    </message>
    <message>
        <source>PDF report, A3 (*.pdf)</source>
        <translation>Rapport PDF, A3 (*.pdf)</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1 : %2</translation>
    </message>
    <message>
        <source>&amp;Getting Started</source>
        <translation>P&amp;remiers pas</translation>
    </message>
    <message>
        <source>A short guide through a first plan</source>
        <translation>Un court guide pour réaliser un premier plan</translation>
    </message>
    <message>
        <source>&amp;Welcome Page</source>
        <translation>Page d’&amp;accueil</translation>
    </message>
    <message>
        <source>The sample plans and the ways to start</source>
        <translation>Les plans d’exemple et les façons de commencer</translation>
    </message>
    <message>
        <source>Opened %1: %2</source>
        <translation>%1 ouvert : %2</translation>
    </message>
</context>
<context>
    <name>fc::ui::OverlayLayer</name>
    <message>
        <source>Primary Cells</source>
        <translation>Cellules primaires</translation>
    </message>
    <message>
        <source>Transition Cells</source>
        <translation>Cellules de transition</translation>
    </message>
    <message>
        <source>Critical Slices</source>
        <translation>Tranches critiques</translation>
    </message>
    <message>
        <source>Corner Nodes</source>
        <translation>Nœuds de coin</translation>
    </message>
    <message>
        <source>Coverage Edges</source>
        <translation>Arêtes de couverture</translation>
    </message>
    <message>
        <source>Contour Edges</source>
        <translation>Arêtes de contour</translation>
    </message>
    <message>
        <source>Inter-cell Edges</source>
        <translation>Arêtes entre cellules</translation>
    </message>
    <message>
        <source>Path</source>
        <translation>Trajet</translation>
    </message>
    <message>
        <source>Overlap Segments</source>
        <translation>Chevauchements</translation>
    </message>
    <message>
        <source>Unreachable Areas</source>
        <translation>Zones inaccessibles</translation>
    </message>
    <message>
        <source>Unreachable: %1 (%2 m²)</source>
        <translation>Inaccessible : %1 (%2 m²)</translation>
    </message>
    <message>
        <source>Coverage Gaps</source>
        <translation>Zones non couvertes</translation>
    </message>
    <message>
        <source>The cells the floor is split into, one colour per room, with their numbers</source>
        <translation>Les cellules qui découpent le sol, une couleur par pièce, avec leurs numéros</translation>
    </message>
    <message>
        <source>Narrow strips between cells the robot passes through (hatched)</source>
        <translation>Bandes étroites entre cellules que le robot traverse (hachurées)</translation>
    </message>
    <message>
        <source>Where the floor&apos;s shape changes and one cell ends (dashed)</source>
        <translation>Là où la forme du sol change et où une cellule se termine (en tirets)</translation>
    </message>
    <message>
        <source>The cells&apos; corners, where the path may enter or leave a cell</source>
        <translation>Les coins des cellules, où le trajet peut entrer dans une cellule ou en sortir</translation>
    </message>
    <message>
        <source>Which corners a cell&apos;s stripes join (entry and exit pairs)</source>
        <translation>Les coins que relient les bandes d’une cellule (paires entrée-sortie)</translation>
    </message>
    <message>
        <source>Moves along a cell&apos;s edge between its corners</source>
        <translation>Déplacements le long du bord d’une cellule, entre ses coins</translation>
    </message>
    <message>
        <source>Moves from one cell to the next</source>
        <translation>Déplacements d’une cellule à la suivante</translation>
    </message>
    <message>
        <source>The robot&apos;s path: cleaning stripes in red, transit moves dashed, arrows for the direction</source>
        <translation>Le trajet du robot : bandes de nettoyage en rouge, trajets à vide en tirets, flèches pour le sens</translation>
    </message>
    <message>
        <source>Where the path passes over floor it has already cleaned (blue)</source>
        <translation>Là où le trajet repasse sur du sol déjà nettoyé (bleu)</translation>
    </message>
    <message>
        <source>Floor the robot cannot reach: gaps narrower than the robot, corners beyond its head</source>
        <translation>Sol que le robot ne peut pas atteindre : passages plus étroits que le robot, coins hors de portée de sa tête de nettoyage</translation>
    </message>
    <message>
        <source>Spots the robot could clean but the path misses</source>
        <translation>Zones que le robot pourrait nettoyer mais que le trajet ne couvre pas</translation>
    </message>
</context>
<context>
    <name>fc::ui::PathPreviewBar</name>
    <message>
        <source>Preview</source>
        <translation>Aperçu</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Lecture</translation>
    </message>
    <message>
        <source>Drive the robot along the planned path.</source>
        <translation>Faire parcourir le trajet planifié au robot.</translation>
    </message>
    <message>
        <source>Speed-up over the robot&apos;s real speed.</source>
        <translation>Accélération par rapport à la vitesse réelle du robot.</translation>
    </message>
    <message>
        <source>Position along the path.</source>
        <translation>Position le long du trajet.</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Vitesse</translation>
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
        <translation>(%1 ; %2) m</translation>
    </message>
    <message>
        <source>per room, along its walls</source>
        <translation>par pièce, le long de ses murs</translation>
    </message>
    <message>
        <source>%1°</source>
        <translation>%1°</translation>
    </message>
    <message>
        <source>Rooms planned</source>
        <translation>Pièces planifiées</translation>
    </message>
    <message>
        <source>%1 of %2</source>
        <translation>%1 sur %2</translation>
    </message>
    <message>
        <source>Estimated time</source>
        <translation>Durée estimée</translation>
    </message>
    <message>
        <source>Path length</source>
        <translation>Longueur du trajet</translation>
    </message>
    <message>
        <source>Extra distance</source>
        <translation>Distance supplémentaire</translation>
    </message>
    <message>
        <source>%1 (%2 % over the ideal %3)</source>
        <translation>%1 (%2 % de plus que l’idéal de %3)</translation>
    </message>
    <message>
        <source>Turns</source>
        <translation>Virages</translation>
    </message>
    <message>
        <source>Coverage</source>
        <translation>Couverture</translation>
    </message>
    <message>
        <source>%1 % of the floor the robot can reach</source>
        <translation>%1 % du sol accessible au robot</translation>
    </message>
    <message>
        <source>Missed</source>
        <translation>Non couvert</translation>
    </message>
    <message>
        <source>%1 m²</source>
        <translation>%1 m²</translation>
    </message>
    <message>
        <source>Too narrow for the robot</source>
        <translation>Trop étroit pour le robot</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Démarrer</translation>
    </message>
    <message>
        <source>%1, chosen by the planner</source>
        <translation>%1, choisi par le planificateur</translation>
    </message>
    <message>
        <source>End</source>
        <translation>Arrivée</translation>
    </message>
    <message>
        <source>Planner</source>
        <translation>Planificateur</translation>
    </message>
    <message>
        <source>%1, stripes %2</source>
        <translation>%1, bandes %2</translation>
    </message>
    <message>
        <source>Robot diameter L</source>
        <translation>Diamètre du robot L</translation>
    </message>
    <message>
        <source>Cleaning diameter D</source>
        <translation>Diamètre de nettoyage D</translation>
    </message>
    <message>
        <source>Coverage width W</source>
        <translation>Largeur de couverture W</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Vitesse</translation>
    </message>
    <message>
        <source>%1 m/s</source>
        <translation>%1 m/s</translation>
    </message>
    <message>
        <source>Time per 90° turn</source>
        <translation>Durée par virage de 90°</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>Order</source>
        <translation>Ordre</translation>
    </message>
    <message>
        <source>Room</source>
        <translation>Pièce</translation>
    </message>
    <message>
        <source>Area</source>
        <translation>Surface</translation>
    </message>
    <message>
        <source>Path</source>
        <translation>Trajet</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Durée</translation>
    </message>
    <message>
        <source>not planned</source>
        <translation>non planifiée</translation>
    </message>
    <message>
        <source>Between rooms</source>
        <translation>Entre les pièces</translation>
    </message>
    <message>
        <source>Total</source>
        <translation>Total</translation>
    </message>
    <message>
        <source>S</source>
        <translation>D</translation>
    </message>
    <message>
        <source>E</source>
        <translation>A</translation>
    </message>
    <message>
        <source>Cleaning path</source>
        <translation>Trajet de nettoyage</translation>
    </message>
    <message>
        <source>Transit</source>
        <translation>Trajet à vide</translation>
    </message>
    <message>
        <source>Overlap</source>
        <translation>Chevauchement</translation>
    </message>
    <message>
        <source>Missed spots</source>
        <translation>Zones non couvertes</translation>
    </message>
    <message>
        <source>Too narrow</source>
        <translation>Trop étroit</translation>
    </message>
    <message>
        <source>Rooms in cleaning order</source>
        <translation>Pièces dans l’ordre de nettoyage</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>Impossible d’écrire %1 : %2</translation>
    </message>
    <message>
        <source>Cleaning plan: %1</source>
        <translation>Plan de nettoyage : %1</translation>
    </message>
    <message>
        <source>Cannot write %1.</source>
        <translation>Impossible d’écrire %1.</translation>
    </message>
    <message>
        <source>Summary</source>
        <translation>Résumé</translation>
    </message>
    <message>
        <source>Robot profile</source>
        <translation>Profil du robot</translation>
    </message>
</context>
<context>
    <name>fc::ui::PickRoomTool</name>
    <message>
        <source>Pick Rooms</source>
        <translation>Choisir les pièces</translation>
    </message>
    <message>
        <source>Pick Rooms: click a room to include it in or exclude it from planning.</source>
        <translation>Choisir les pièces : cliquez une pièce pour l’inclure dans la planification ou l’en exclure.</translation>
    </message>
    <message>
        <source>No room here.</source>
        <translation>Aucune pièce ici.</translation>
    </message>
</context>
<context>
    <name>fc::ui::PlaceEndpointTool</name>
    <message>
        <source>Place Start</source>
        <translation>Placer le départ</translation>
    </message>
    <message>
        <source>Place End</source>
        <translation>Placer l’arrivée</translation>
    </message>
    <message>
        <source>Place End: click where the robot should finish; right-click removes it (the path then returns to the start).</source>
        <translation>Placer l’arrivée : cliquez là où le robot doit finir ; clic droit pour la retirer (le trajet revient alors au départ).</translation>
    </message>
    <message>
        <source>S</source>
        <translation>D</translation>
    </message>
    <message>
        <source>E</source>
        <translation>A</translation>
    </message>
    <message>
        <source>%1: the point must lie inside the floor.</source>
        <translation>%1 : le point doit se trouver dans la surface.</translation>
    </message>
    <message>
        <source>Place Start: click where the robot starts (moved off a wall to where the robot fits); right-click removes it.</source>
        <translation>Placer le départ : cliquez là où le robot part (écarté d’un mur jusqu’où le robot tient) ; clic droit pour le retirer.</translation>
    </message>
    <message>
        <source>%1: that point is inside an obstacle; click on the floor.</source>
        <translation>%1 : ce point est dans un obstacle ; cliquez sur le sol.</translation>
    </message>
    <message>
        <source>%1: the robot (%2 m across) does not fit there or nearby.</source>
        <translation>%1 : le robot (%2 m de large) ne tient ni là ni à proximité.</translation>
    </message>
    <message>
        <source>%1: moved %2 m off the wall, where the robot fits.</source>
        <translation>%1 : déplacé de %2 m loin du mur, là où le robot tient.</translation>
    </message>
</context>
<context>
    <name>fc::ui::PlanScene</name>
    <message>
        <source>%1 (planned)</source>
        <translation>%1 (planifiée)</translation>
    </message>
    <message>
        <source>%1 (not planned)</source>
        <translation>%1 (non planifiée)</translation>
    </message>
    <message>
        <source>S</source>
        <translation>D</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Départ</translation>
    </message>
    <message>
        <source>E</source>
        <translation>A</translation>
    </message>
    <message>
        <source>End</source>
        <translation>Arrivée</translation>
    </message>
    <message>
        <source>The corner the planner starts or ends at</source>
        <translation>Le coin où le planificateur commence ou finit</translation>
    </message>
    <message>
        <source>Start, chosen by the planner</source>
        <translation>Départ, choisi par le planificateur</translation>
    </message>
    <message>
        <source>End of the path</source>
        <translation>Fin du trajet</translation>
    </message>
</context>
<context>
    <name>fc::ui::PlanningController</name>
    <message>
        <source>Preparing the overlays</source>
        <translation>Préparation des calques</translation>
    </message>
    <message>
        <source>Planning the path</source>
        <translation>Planification du trajet</translation>
    </message>
    <message>
        <source>Sketching the path</source>
        <translation>Esquisse du trajet</translation>
    </message>
    <message>
        <source>This plan has problems: repair it first (Plan &gt; Repair Plan, or the button in the Problems panel).</source>
        <translation>Ce plan a des problèmes : réparez-le d’abord (Planifier &gt; Réparer le plan, ou le bouton du panneau Problèmes).</translation>
    </message>
</context>
<context>
    <name>fc::ui::PlanningDock</name>
    <message>
        <source>Planning</source>
        <translation>Planification</translation>
    </message>
    <message>
        <source>Rooms to plan</source>
        <translation>Pièces à planifier</translation>
    </message>
    <message>
        <source>Plan</source>
        <translation>Planifier</translation>
    </message>
    <message>
        <source>Plan the coverage path for the checked rooms (F5).</source>
        <translation>Planifier le trajet de couverture des pièces cochées (F5).</translation>
    </message>
    <message>
        <source>Robot</source>
        <translation>Robot</translation>
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
        <translation>Diamètre du robot L</translation>
    </message>
    <message>
        <source>Cleaning diameter D</source>
        <translation>Diamètre de nettoyage D</translation>
    </message>
    <message>
        <source>Coverage width W</source>
        <translation>Largeur de couverture W</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Vitesse</translation>
    </message>
    <message>
        <source>Time per 90° turn</source>
        <translation>Durée par virage de 90°</translation>
    </message>
    <message>
        <source>Sweep</source>
        <translation>Balayage</translation>
    </message>
    <message>
        <source>°</source>
        <translation>°</translation>
    </message>
    <message>
        <source>Stripe angle</source>
        <translation>Angle des bandes</translation>
    </message>
    <message>
        <source>Solver</source>
        <translation>Solveur</translation>
    </message>
    <message>
        <source>Metrics</source>
        <translation>Mesures</translation>
    </message>
    <message>
        <source>Length</source>
        <translation>Longueur</translation>
    </message>
    <message>
        <source>Extra distance</source>
        <translation>Distance supplémentaire</translation>
    </message>
    <message>
        <source>Turns</source>
        <translation>Virages</translation>
    </message>
    <message>
        <source>Coverage</source>
        <translation>Couverture</translation>
    </message>
    <message>
        <source>Estimated time</source>
        <translation>Durée estimée</translation>
    </message>
    <message>
        <source>Cells</source>
        <translation>Cellules</translation>
    </message>
    <message>
        <source>Planning time</source>
        <translation>Temps de planification</translation>
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
        <translation>Planification…</translation>
    </message>
    <message>
        <source>Draw the boundary of the floor to see cells and plan a path.</source>
        <translation>Dessinez le contour de la surface pour voir les cellules et planifier un trajet.</translation>
    </message>
    <message>
        <source>Per room, along its walls</source>
        <translation>Par pièce, le long de ses murs</translation>
    </message>
    <message>
        <source>Auto: fastest full coverage</source>
        <translation>Auto : couverture complète la plus rapide</translation>
    </message>
    <message>
        <source>One angle for the floor</source>
        <translation>Un angle pour tout l’étage</translation>
    </message>
    <message>
        <source>Per room: each room&apos;s stripes follow its own walls (set a room&apos;s angle below to override it). Auto: tries several angles for the whole floor and keeps the fastest plan that covers everything the robot can reach. One angle: the stripe angle below for every room.</source>
        <translation>Par pièce : les bandes de chaque pièce suivent ses propres murs (fixez ci-dessous l’angle d’une pièce pour l’imposer). Auto : essaie plusieurs angles pour tout l’étage et garde le plan le plus rapide qui couvre tout ce que le robot peut atteindre. Un angle : l’angle des bandes ci-dessous pour chaque pièce.</translation>
    </message>
    <message>
        <source>Room</source>
        <translation>Pièce</translation>
    </message>
    <message>
        <source>From walls</source>
        <translation>Selon les murs</translation>
    </message>
    <message>
        <source>Fixed</source>
        <translation>Imposé</translation>
    </message>
    <message>
        <source>Uncovered</source>
        <translation>Non couvert</translation>
    </message>
    <message>
        <source>Unreachable</source>
        <translation>Inaccessible</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not an angle in degrees.</source>
        <translation>« %1 » n’est pas un angle en degrés.</translation>
    </message>
    <message>
        <source>%1 m² (%2 %)</source>
        <translation>%1 m² (%2 %)</translation>
    </message>
    <message>
        <source>Check the rooms to cover; double-click a name to rename the room. Select two rooms (Ctrl+click) to merge them; split a room with the Split Room tool (K).</source>
        <translation>Cochez les pièces à couvrir ; double-cliquez sur un nom pour renommer la pièce. Sélectionnez deux pièces (Ctrl+clic) pour les fusionner ; divisez une pièce avec l&apos;outil Diviser la pièce (K).</translation>
    </message>
    <message>
        <source>Merge Selected Rooms</source>
        <translation>Fusionner les pièces sélectionnées</translation>
    </message>
    <message>
        <source>Join the two selected rooms into one (they must share a wall or a doorway); the first keeps its name.</source>
        <translation>Réunir les deux pièces sélectionnées en une seule (elles doivent partager un mur ou une porte) ; la première garde son nom.</translation>
    </message>
    <message>
        <source>A quick sketch of the path is shown; the planner is refining it…</source>
        <translation>Une esquisse rapide du trajet est affichée ; le planificateur l’affine…</translation>
    </message>
    <message>
        <source>The robot&apos;s body, L: its centre keeps L/2 from walls, and doors narrower than L are not passed.</source>
        <translation>Le corps du robot, L : son centre reste à L/2 des murs, et il ne passe pas les portes plus étroites que L.</translation>
    </message>
    <message>
        <source>The width the cleaning head reaches, D (at least W).</source>
        <translation>La largeur couverte par la tête de nettoyage, D (au moins W).</translation>
    </message>
    <message>
        <source>Distance between neighbouring stripes, W (between L and D): smaller overlaps more, larger risks gaps.</source>
        <translation>Distance entre bandes voisines, W (entre L et D) : plus petite, plus de chevauchement ; plus grande, risque de zones oubliées.</translation>
    </message>
    <message>
        <source>Driving speed, for the estimated time.</source>
        <translation>Vitesse de déplacement, pour la durée estimée.</translation>
    </message>
    <message>
        <source>Seconds the robot needs to turn by 90°, for the estimated time.</source>
        <translation>Secondes nécessaires au robot pour tourner de 90°, pour la durée estimée.</translation>
    </message>
    <message>
        <source>The stripes&apos; direction in degrees (90 = vertical), for One angle for the floor.</source>
        <translation>La direction des bandes en degrés (90 = verticale), pour « Un angle pour tout l’étage ».</translation>
    </message>
    <message>
        <source>How the order of the cells is chosen: heuristic is fast and close to the best; exact proves the best order on small floors; greedy is the quickest sketch; dqn uses the model trained in the Training panel, or the built-in generalist model when none is; dqn-search lets that model guide a search for 2 seconds per part of the floor (better than heuristic on large floors).</source>
        <translation>Comment l’ordre des cellules est choisi : heuristic est rapide et proche du meilleur ; exact prouve le meilleur ordre sur les petits plans ; greedy est l’esquisse la plus rapide ; dqn utilise le modèle entraîné dans le panneau Entraînement, ou le modèle généraliste intégré s’il n’y en a pas ; dqn-search laisse ce modèle guider une recherche pendant 2 secondes par partie du plan (meilleur que heuristic sur les grands plans).</translation>
    </message>
    <message>
        <source>Planned</source>
        <translation>Planifié</translation>
    </message>
    <message>
        <source>Type an angle in degrees to fix a room&apos;s stripes; clear it to follow the room&apos;s walls again. Planned: the angle the last plan swept the room at (the planner may turn a room by 90° or along its other walls where that plans faster).</source>
        <translation>Saisir un angle en degrés pour fixer les bandes d&apos;une pièce ; l&apos;effacer pour suivre de nouveau ses murs. Planifié : l&apos;angle auquel le dernier plan a balayé la pièce (le planificateur peut tourner une pièce de 90° ou la caler sur ses autres murs quand c&apos;est plus rapide).</translation>
    </message>
    <message numerus="yes">
        <source>Wall teeth cut back to their walls for planning: %n (pilasters, bumps of traced walls); the path keeps clear of them.</source>
        <translation>
            <numerusform>Saillies de mur ramenées à la ligne du mur pour la planification : %n (pilastres, bosses de murs scannés) ; le chemin s’en tient à distance.</numerusform>
            <numerusform>Saillies de mur ramenées à la ligne du mur pour la planification : %n (pilastres, bosses de murs scannés) ; le chemin s’en tient à distance.</numerusform>
        </translation>
    </message>
    <message>
        <source>Planned as loops along the walls, each one coverage width further in: estimated faster than stripes on this floor.</source>
        <translation>Planifié en boucles le long des murs, chacune d’une largeur de nettoyage plus à l’intérieur : estimé plus rapide que des bandes sur cette surface.</translation>
    </message>
</context>
<context>
    <name>fc::ui::PpoTrainer</name>
    <message>
        <source>Training ppo</source>
        <translation>Entraînement PPO</translation>
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
        <translation>Durée d’entraînement de la politique ppo (elle apprend sur des pièces aléatoires : un modèle sert à tous les plans)</translation>
    </message>
    <message>
        <source>Train ppo</source>
        <translation>Entraîner ppo</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Arrêter</translation>
    </message>
    <message>
        <source>ppo trains on first use (about a minute); train it here to watch it learn.</source>
        <translation>ppo s’entraîne à la première utilisation (environ une minute) ; entraînez-le ici pour le voir apprendre.</translation>
    </message>
    <message>
        <source>PPO update</source>
        <translation>Mise à jour PPO</translation>
    </message>
    <message>
        <source>Energy per waypoint (kg m)</source>
        <translation>Énergie par point de passage (kg m)</translation>
    </message>
    <message>
        <source>Trained for %1 updates; ppo now plans with %2.</source>
        <translation>Entraîné sur %1 mises à jour ; ppo planifie désormais avec %2.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Training failed:&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;Échec de l’entraînement :&lt;/b&gt; %1</translation>
    </message>
    <message>
        <source>Training…</source>
        <translation>Entraînement…</translation>
    </message>
    <message>
        <source>Update %1, %2 kg m per waypoint, %3 s</source>
        <translation>Mise à jour %1, %2 kg m par point de passage, %3 s</translation>
    </message>
    <message>
        <source>Training cancelled before its first update; no model.</source>
        <translation>Entraînement annulé avant sa première mise à jour ; aucun modèle.</translation>
    </message>
    <message>
        <source>Train the learnt ordering (ppo) in the background for the time set.</source>
        <translation>Entraîner l’ordre appris (ppo) en arrière-plan pendant la durée choisie.</translation>
    </message>
    <message>
        <source>End training; what was learnt so far is kept.</source>
        <translation>Terminer l’entraînement ; ce qui a été appris jusqu’ici est conservé.</translation>
    </message>
</context>
<context>
    <name>fc::ui::PreferencesDialog</name>
    <message>
        <source>Preferences</source>
        <translation>Préférences</translation>
    </message>
    <message>
        <source>The language changes at the next start of FloorCover.</source>
        <translation>La langue change au prochain démarrage de FloorCover.</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Langue</translation>
    </message>
    <message>
        <source>The language of the editor, its messages and Qt&apos;s dialogs</source>
        <translation>La langue de l’éditeur, de ses messages et des boîtes de dialogue de Qt</translation>
    </message>
</context>
<context>
    <name>fc::ui::ProblemsDock</name>
    <message>
        <source>Problems</source>
        <translation>Problèmes</translation>
    </message>
    <message>
        <source>Repair Plan</source>
        <translation>Réparer le plan</translation>
    </message>
    <message>
        <source>&amp;Repair Plan</source>
        <translation>Réparer &amp;le plan</translation>
    </message>
    <message>
        <source>Click a problem to see where it is on the plan.</source>
        <translation>Cliquez sur un problème pour voir où il se trouve sur le plan.</translation>
    </message>
    <message>
        <source>Makes the plan valid: walls that cross themselves are split where they cross, obstacles that overlap or cross the wall are merged or clipped, rooms are fitted to the floor. Undo (Ctrl+Z) brings the plan back as it was.</source>
        <translation>Rend le plan valide : les murs qui se croisent sont coupés à leurs croisements, les obstacles qui se chevauchent ou traversent le mur sont fusionnés ou découpés, les pièces sont ajustées au sol. Annuler (Ctrl+Z) rétablit le plan tel qu’il était.</translation>
    </message>
    <message numerus="yes">
        <source>This plan cannot be planned as it is: %n problem(s). It is open read-only and nothing is lost; repair it to plan.</source>
        <translation>
            <numerusform>Ce plan ne peut pas être planifié tel quel : %n problème. Il est ouvert en lecture seule et rien n’est perdu ; réparez-le pour planifier.</numerusform>
            <numerusform>Ce plan ne peut pas être planifié tel quel : %n problèmes. Il est ouvert en lecture seule et rien n’est perdu ; réparez-le pour planifier.</numerusform>
        </translation>
    </message>
    <message>
        <source>Repaired. What changed (Edit &gt; Undo brings the old plan back):</source>
        <translation>Réparé. Ce qui a changé (Édition &gt; Annuler rétablit l’ancien plan) :</translation>
    </message>
    <message>
        <source>No problems: the plan can be planned.</source>
        <translation>Aucun problème : le plan peut être planifié.</translation>
    </message>
</context>
<context>
    <name>fc::ui::SiteBuildingChoice</name>
    <message>
        <source>Building %1 (%2 m²)</source>
        <translation>Bâtiment %1 (%2 m²)</translation>
    </message>
    <message>
        <source>Choose a Building</source>
        <translation>Choisir un bâtiment</translation>
    </message>
    <message>
        <source>%1 holds %2 buildings, and a plan holds one.
Which building do you want to open?</source>
        <translation>%1 contient %2 bâtiments, et un plan n’en contient qu’un.
Quel bâtiment voulez-vous ouvrir ?</translation>
    </message>
</context>
<context>
    <name>fc::ui::SplitRoomTool</name>
    <message>
        <source>Split Room</source>
        <translation>Diviser la pièce</translation>
    </message>
    <message>
        <source>Split Room: drag a line across a room to cut it in two (Esc cancels); the larger part keeps the name.</source>
        <translation>Diviser la pièce : tracez une ligne à travers une pièce pour la couper en deux (Échap annule) ; la plus grande partie garde le nom.</translation>
    </message>
    <message>
        <source>Split Room: drag the cut across the room.</source>
        <translation>Diviser la pièce : tracez la coupe à travers la pièce.</translation>
    </message>
    <message>
        <source>Split Room: the cut must cross a room.</source>
        <translation>Diviser la pièce : la coupe doit traverser une pièce.</translation>
    </message>
    <message>
        <source>Split %1 in two.</source>
        <translation>%1 divisée en deux.</translation>
    </message>
</context>
<context>
    <name>fc::ui::TaskListWidget</name>
    <message>
        <source>Cancel</source>
        <translation>Annuler</translation>
    </message>
    <message>
        <source>Cancel: %1</source>
        <translation>Annuler : %1</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1 : %2</translation>
    </message>
    <message>
        <source>%1 (cancelling…)</source>
        <translation>%1 (annulation…)</translation>
    </message>
</context>
<context>
    <name>fc::ui::TilingController</name>
    <message>
        <source>Tiling with %1</source>
        <translation>Pavage avec %1</translation>
    </message>
</context>
<context>
    <name>fc::ui::TilingDock</name>
    <message>
        <source>Tiling Robot</source>
        <translation>Robot à pavage</translation>
    </message>
    <message>
        <source>How the tiles are ordered: zigzag and spiral follow the rows, greedy, aco and ga minimise the energy, exact only for a few tiles, ppo is the learnt pointer network.</source>
        <translation>Ordre des tuiles : zigzag et spiral suivent les rangées, greedy, aco et ga minimisent l’énergie, exact seulement pour peu de tuiles, ppo est le réseau pointeur appris.</translation>
    </message>
    <message>
        <source>Ordering:</source>
        <translation>Ordre :</translation>
    </message>
    <message>
        <source>Seed:</source>
        <translation>Graine :</translation>
    </message>
    <message>
        <source> m</source>
        <translation> m</translation>
    </message>
    <message>
        <source>Block leg:</source>
        <translation>Côté de bloc :</translation>
    </message>
    <message>
        <source>Mass of block B%1 in kg</source>
        <translation>Masse du bloc B%1 en kg</translation>
    </message>
    <message>
        <source>Block masses (kg):</source>
        <translation>Masses des blocs (kg) :</translation>
    </message>
    <message>
        <source>Tile and Order</source>
        <translation>Paver et ordonner</translation>
    </message>
    <message>
        <source>Show tiles on the canvas</source>
        <translation>Afficher les tuiles sur le plan</translation>
    </message>
    <message>
        <source>Export Waypoints…</source>
        <translation>Exporter les points de passage…</translation>
    </message>
    <message>
        <source>Learnt ordering (ppo)</source>
        <translation>Ordre appris (ppo)</translation>
    </message>
    <message>
        <source>Tiling and ordering… (ppo trains its network first)</source>
        <translation>Pavage et ordonnancement… (ppo entraîne d’abord son réseau)</translation>
    </message>
    <message>
        <source>Tiling and ordering…</source>
        <translation>Pavage et ordonnancement…</translation>
    </message>
    <message>
        <source>&lt;b&gt;Cannot tile:&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;Pavage impossible :&lt;/b&gt; %1</translation>
    </message>
    <message>
        <source>Press “Tile and Order” to cover the floor with the robot&apos;s shapes and order the tiles by energy.</source>
        <translation>Cliquez sur « Paver et ordonner » pour couvrir le sol avec les formes du robot et ordonner les tuiles selon l’énergie.</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;: energy %2 kg m (translation %3, shape changes %4, turns %5)&lt;br&gt;%6 waypoints, %7 m, %8 shape changes, ordered in %9 s&lt;br&gt;%10 cells free, %11 left untiled, %12 unreachable (red)&lt;br&gt;%13</source>
        <translation>&lt;b&gt;%1&lt;/b&gt; : énergie %2 kg m (translation %3, changements de forme %4, rotations %5)&lt;br&gt;%6 points de passage, %7 m, %8 changements de forme, ordonné en %9 s&lt;br&gt;%10 cellules libres, %11 non pavées, %12 inaccessibles (rouge)&lt;br&gt;%13</translation>
    </message>
    <message>
        <source>No tiling to export: press “Tile and Order” first.</source>
        <translation>Aucun pavage à exporter : cliquez d’abord sur « Paver et ordonner ».</translation>
    </message>
    <message>
        <source>Export Waypoints</source>
        <translation>Exporter les points de passage</translation>
    </message>
    <message>
        <source>CSV (*.csv);;JSON (*.json)</source>
        <translation>CSV (*.csv);;JSON (*.json)</translation>
    </message>
    <message>
        <source>&lt;b&gt;Export failed:&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;Échec de l’export :&lt;/b&gt; %1</translation>
    </message>
    <message>
        <source>Random seed of the ordering methods that use chance (aco, ga, ppo): the same seed gives the same tour.</source>
        <translation>Graine aléatoire des méthodes d’ordre qui utilisent le hasard (aco, ga, ppo) : la même graine donne le même parcours.</translation>
    </message>
    <message>
        <source>Side of one block of the tiling robot in metres.</source>
        <translation>Côté d’un bloc du robot à pavage, en mètres.</translation>
    </message>
    <message>
        <source>Tile the floor with the robot&apos;s shapes and order the tiles by energy.</source>
        <translation>Paver le sol avec les formes du robot et ordonner les tuiles selon l’énergie.</translation>
    </message>
    <message>
        <source>Draw the tiles and their tour over the plan.</source>
        <translation>Afficher les tuiles et leur parcours sur le plan.</translation>
    </message>
    <message>
        <source>Write the ordered waypoints (position, shape, heading) as CSV or JSON for the robot.</source>
        <translation>Écrire les points de passage ordonnés (position, forme, orientation) en CSV ou JSON pour le robot.</translation>
    </message>
</context>
<context>
    <name>fc::ui::TilingMode</name>
    <message>
        <source>&amp;Tiling Robot Mode</source>
        <translation>Mode robot à &amp;pavage</translation>
    </message>
    <message>
        <source>Cover the floor with a shape-shifting tiling robot&apos;s tiles and order them by energy</source>
        <translation>Couvrir le sol avec les tuiles d’un robot à pavage reconfigurable et les ordonner selon l’énergie</translation>
    </message>
</context>
<context>
    <name>fc::ui::TrainingDock</name>
    <message>
        <source>Training</source>
        <translation>Entraînement</translation>
    </message>
    <message>
        <source>Improved</source>
        <translation>Amélioré</translation>
    </message>
    <message>
        <source>Paper</source>
        <translation>Comme l’article</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Training time for one run</source>
        <translation>Durée d’entraînement d’une exécution</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Démarrer</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Arrêter</translation>
    </message>
    <message>
        <source>No model yet</source>
        <translation>Pas encore de modèle</translation>
    </message>
    <message>
        <source>Episode</source>
        <translation>Épisode</translation>
    </message>
    <message>
        <source>Reward</source>
        <translation>Récompense</translation>
    </message>
    <message>
        <source>Loss / epsilon</source>
        <translation>Perte / epsilon</translation>
    </message>
    <message>
        <source>Episode reward</source>
        <translation>Récompense par épisode</translation>
    </message>
    <message>
        <source>Moving average (100)</source>
        <translation>Moyenne mobile (100)</translation>
    </message>
    <message>
        <source>Loss</source>
        <translation>Perte</translation>
    </message>
    <message>
        <source>Epsilon</source>
        <translation>Epsilon</translation>
    </message>
    <message>
        <source>Save Model…</source>
        <translation>Enregistrer le modèle…</translation>
    </message>
    <message>
        <source>Load Model…</source>
        <translation>Charger un modèle…</translation>
    </message>
    <message>
        <source>The plan changed: the model no longer fits it. Start to train for the new plan.</source>
        <translation>Le plan a changé : le modèle ne lui correspond plus. Lancez l’entraînement pour le nouveau plan.</translation>
    </message>
    <message>
        <source>There is no valid plan to train for.</source>
        <translation>Aucun plan valide pour l’entraînement.</translation>
    </message>
    <message>
        <source>Episode %1 · %2 steps/s · epsilon %3 · average reward %4</source>
        <translation>Épisode %1 · %2 pas/s · epsilon %3 · récompense moyenne %4</translation>
    </message>
    <message>
        <source>%1% · %2 left</source>
        <translation>%1 % · reste %2</translation>
    </message>
    <message>
        <source>Model after %1 episodes (%2 of training) ready for solver dqn</source>
        <translation>Modèle après %1 épisodes (%2 d’entraînement) prêt pour le solveur dqn</translation>
    </message>
    <message>
        <source>Pause the training before saving the model.</source>
        <translation>Mettez l’entraînement en pause avant d’enregistrer le modèle.</translation>
    </message>
    <message>
        <source>Cannot save the model to %1: %2</source>
        <translation>Impossible d’enregistrer le modèle dans %1 : %2</translation>
    </message>
    <message>
        <source>Stop the training before loading a model.</source>
        <translation>Arrêtez l’entraînement avant de charger un modèle.</translation>
    </message>
    <message>
        <source>Loaded %1 (%2 episodes of training)</source>
        <translation>%1 chargé (%2 épisodes d’entraînement)</translation>
    </message>
    <message>
        <source>Save Model</source>
        <translation>Enregistrer le modèle</translation>
    </message>
    <message>
        <source>FloorCover DQN model (*.fcdqn)</source>
        <translation>Modèle DQN FloorCover (*.fcdqn)</translation>
    </message>
    <message>
        <source>Load Model</source>
        <translation>Charger un modèle</translation>
    </message>
    <message>
        <source>%p%</source>
        <translation>%p %</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Reprendre</translation>
    </message>
    <message>
        <source>Graph state</source>
        <translation>État de graphe</translation>
    </message>
    <message>
        <source>Improved: masking, graph-cost reward, cost channels and a refined walk. Graph state: the same with per-corner features and a per-corner network (faster on large floors). Paper: the published setting.</source>
        <translation>Amélioré : masquage, récompense par coût de graphe, canaux de coût et parcours affiné. État de graphe : la même chose avec des caractéristiques par coin et un réseau par coin (plus rapide sur les grands plans). Article : le réglage publié.</translation>
    </message>
    <message>
        <source>Evaluate</source>
        <translation>Évaluer</translation>
    </message>
    <message>
        <source>Plan the model&apos;s test queries with it and compare with the exact or heuristic solver</source>
        <translation>Planifier les requêtes de test du modèle avec lui et comparer au solveur exact ou heuristique</translation>
    </message>
    <message>
        <source>Evaluating the model on its test queries…</source>
        <translation>Évaluation du modèle sur ses requêtes de test…</translation>
    </message>
    <message>
        <source>On %1 test queries: the policy alone is %2% above the %3 solver; solver dqn is %4% above it, %5 ms per query.</source>
        <translation>Sur %1 requêtes de test : la politique seule est à %2 % au-dessus du solveur %3 ; le solveur dqn à %4 %, %5 ms par requête.</translation>
    </message>
    <message numerus="yes">
        <source>%n queries did not finish.</source>
        <translation>
            <numerusform>%n requête n’a pas abouti.</numerusform>
            <numerusform>%n requêtes n’ont pas abouti.</numerusform>
        </translation>
    </message>
    <message>
        <source>Evaluation cancelled.</source>
        <translation>Évaluation annulée.</translation>
    </message>
    <message>
        <source>Evaluation failed: %1</source>
        <translation>Échec de l’évaluation : %1</translation>
    </message>
    <message>
        <source>Training the DQN</source>
        <translation>Entraînement du DQN</translation>
    </message>
    <message>
        <source>there is no trained model yet</source>
        <translation>il n’y a pas encore de modèle entraîné</translation>
    </message>
    <message>
        <source>Evaluating the DQN model</source>
        <translation>Évaluation du modèle DQN</translation>
    </message>
    <message>
        <source>Training failed: %1</source>
        <translation>Échec de l’entraînement : %1</translation>
    </message>
    <message>
        <source>Training cannot start: %1</source>
        <translation>L’entraînement ne peut pas démarrer : %1</translation>
    </message>
    <message>
        <source>Done · %1 trained</source>
        <translation>Terminé · %1 d’entraînement</translation>
    </message>
    <message>
        <source>Paused at %p% · %1 trained</source>
        <translation>En pause à %p% · %1 d’entraînement</translation>
    </message>
    <message>
        <source>cannot replace the file</source>
        <translation>impossible de remplacer le fichier</translation>
    </message>
    <message>
        <source>Train the learnt planner (solver dqn) for this plan in the background; the curve shows its reward per episode.</source>
        <translation>Entraîner le planificateur appris (solveur dqn) pour ce plan en arrière-plan ; la courbe montre sa récompense par épisode.</translation>
    </message>
    <message>
        <source>Pause training and keep the model so far; Resume goes on.</source>
        <translation>Mettre l’entraînement en pause et garder le modèle obtenu ; Reprendre le poursuit.</translation>
    </message>
    <message>
        <source>End training; the model so far is kept for solver dqn.</source>
        <translation>Terminer l’entraînement ; le modèle obtenu est conservé pour le solveur dqn.</translation>
    </message>
    <message>
        <source>Save the trained model to a .fcdqn file (saving the project also saves it beside the project).</source>
        <translation>Enregistrer le modèle entraîné dans un fichier .fcdqn (l’enregistrement du projet l’enregistre aussi à côté du projet).</translation>
    </message>
    <message>
        <source>Load a model trained for this plan from a .fcdqn file.</source>
        <translation>Charger depuis un fichier .fcdqn un modèle entraîné pour ce plan.</translation>
    </message>
    <message>
        <source>there is no valid plan to load the model for</source>
        <translation>il n’y a pas de plan valide pour lequel charger le modèle</translation>
    </message>
    <message>
        <source>Policy gap (%)</source>
        <translation>Écart de la politique (%)</translation>
    </message>
    <message>
        <source>Policy alone, % above the reference</source>
        <translation>Politique seule, % au-dessus de la référence</translation>
    </message>
    <message>
        <source> · policy alone %1 % above the reference</source>
        <translation> · politique seule %1 % au-dessus de la référence</translation>
    </message>
    <message>
        <source>From the generalist</source>
        <translation>Depuis le généraliste</translation>
    </message>
    <message>
        <source>Start from the built-in generalist model, trained on generated floors (what solver dqn uses before any training), and fine-tune it for this plan. Off: start from random weights. Graph state only.</source>
        <translation>Partir du modèle généraliste intégré, entraîné sur des plans générés (celui qu’utilise le solveur dqn avant tout entraînement), et l’affiner pour ce plan. Désactivé : partir de poids aléatoires. État graphe seulement.</translation>
    </message>
</context>
<context>
    <name>fc::ui::Translations</name>
    <message>
        <source>System language</source>
        <translation>Langue du système</translation>
    </message>
</context>
<context>
    <name>fc::ui::WelcomeDialog</name>
    <message>
        <source>Show this page at start</source>
        <translation>Afficher cette page au démarrage</translation>
    </message>
    <message>
        <source>Welcome to FloorCover</source>
        <translation>Bienvenue dans FloorCover</translation>
    </message>
    <message>
        <source>&lt;h2&gt;Welcome to FloorCover&lt;/h2&gt;&lt;p&gt;FloorCover plans the path a cleaning or disinfection robot drives to cover a floor:&lt;/p&gt;&lt;ol&gt;&lt;li&gt;&lt;b&gt;Bring a floor plan&lt;/b&gt;: draw it, import a CAD drawing or the robot&apos;s map, or try a sample below.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Choose the rooms&lt;/b&gt; to clean and where the robot starts.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Check the path&lt;/b&gt; and its time, then export it for the robot or print a report.&lt;/li&gt;&lt;/ol&gt;</source>
        <translation>&lt;h2&gt;Bienvenue dans FloorCover&lt;/h2&gt;&lt;p&gt;FloorCover planifie le trajet qu’un robot de nettoyage ou de désinfection parcourt pour couvrir un sol :&lt;/p&gt;&lt;ol&gt;&lt;li&gt;&lt;b&gt;Apportez un plan d’étage&lt;/b&gt; : dessinez-le, importez un dessin CAO ou la carte du robot, ou essayez un exemple ci-dessous.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Choisissez les pièces&lt;/b&gt; à nettoyer et le point de départ du robot.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Vérifiez le trajet&lt;/b&gt; et sa durée, puis exportez-le pour le robot ou imprimez un rapport.&lt;/li&gt;&lt;/ol&gt;</translation>
    </message>
    <message>
        <source>Double-click a sample to open it</source>
        <translation>Double-cliquez sur un exemple pour l’ouvrir</translation>
    </message>
    <message>
        <source>Open Sample</source>
        <translation>Ouvrir un exemple</translation>
    </message>
    <message>
        <source>Open the selected sample plan</source>
        <translation>Ouvrir le plan d’exemple sélectionné</translation>
    </message>
    <message>
        <source>Draw a New Floor</source>
        <translation>Dessiner un nouveau plan</translation>
    </message>
    <message>
        <source>Start an empty drawing with the Draw Boundary tool</source>
        <translation>Commencer un dessin vide avec l’outil Dessiner le contour</translation>
    </message>
    <message>
        <source>Import a Drawing or Map…</source>
        <translation>Importer un dessin ou une carte…</translation>
    </message>
    <message>
        <source>DXF drawings, the robot&apos;s occupancy map (.yaml), WKT, GeoJSON or 3D building models</source>
        <translation>Dessins DXF, carte d’occupation du robot (.yaml), WKT, GeoJSON ou maquettes 3D de bâtiment</translation>
    </message>
    <message>
        <source>Open a Project…</source>
        <translation>Ouvrir un projet…</translation>
    </message>
    <message>
        <source>Open a saved .fcproj or .geojson</source>
        <translation>Ouvrir un fichier .fcproj ou .geojson enregistré</translation>
    </message>
    <message>
        <source>Getting Started</source>
        <translation>Premiers pas</translation>
    </message>
    <message>
        <source>A short guide through a first plan (F1)</source>
        <translation>Un court guide pour réaliser un premier plan (F1)</translation>
    </message>
    <message>
        <source>Help &gt; Welcome Page shows it again at any time</source>
        <translation>Aide &gt; Page d’accueil la réaffiche à tout moment</translation>
    </message>
    <message>
        <source>Close this page</source>
        <translation>Fermer cette page</translation>
    </message>
    <message>
        <source>&lt;b&gt;Sample plans&lt;/b&gt;</source>
        <translation>&lt;b&gt;Plans d’exemple&lt;/b&gt;</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Coverage path planning for floor plans</source>
        <translation>Planification de trajets de couverture pour plans d’étage</translation>
    </message>
    <message>
        <source>Render the main window with overlays and a planned path to FILE (PNG) and exit.</source>
        <translation>Rendre la fenêtre principale avec les calques et un trajet planifié dans FICHIER (PNG) puis quitter.</translation>
    </message>
    <message>
        <source>FILE</source>
        <translation>FICHIER</translation>
    </message>
    <message>
        <source>A .fcproj or .geojson file.</source>
        <translation>Un fichier .fcproj ou .geojson.</translation>
    </message>
    <message>
        <source>Of a GeoJSON site of several buildings, open building K (1 = the largest) instead of asking.</source>
        <translation>D’un site GeoJSON de plusieurs bâtiments, ouvrir le bâtiment K (1 = le plus grand) au lieu de demander.</translation>
    </message>
</context>
</TS>

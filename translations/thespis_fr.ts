<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="fr_FR">
<context>
    <name>main</name>
    <message>
        <source>Thespis Studio: author and preview virtual humans. Opens SCENARIO, or the built-in demo.</source>
        <translation>Thespis Studio : créer et prévisualiser des humains virtuels. Ouvre SCÉNARIO, ou la démo intégrée.</translation>
    </message>
    <message>
        <source>The scenario file (.thespis) to open.</source>
        <translation>Le fichier de scénario (.thespis) à ouvrir.</translation>
    </message>
    <message>
        <source>Start at SECONDS into the scenario.</source>
        <translation>Commencer à SECONDES dans le scénario.</translation>
    </message>
    <message>
        <source>Save a picture of the window to FILE (PNG) once the scenario is shown, then quit.</source>
        <translation>Enregistrer une image de la fenêtre dans FICHIER (PNG) une fois le scénario affiché, puis quitter.</translation>
    </message>
</context>
<context>
    <name>thespis::editor::Document</name>
    <message>
        <source>Untitled</source>
        <translation>Sans titre</translation>
    </message>
</context>
<context>
    <name>thespis::editor::ErrorDialog</name>
    <message>
        <source>File not found</source>
        <translation>Fichier introuvable</translation>
    </message>
    <message>
        <source>Not a Thespis file</source>
        <translation>Pas un fichier Thespis</translation>
    </message>
    <message>
        <source>The file is damaged</source>
        <translation>Le fichier est endommagé</translation>
    </message>
    <message>
        <source>Made by a newer Thespis</source>
        <translation>Créé par un Thespis plus récent</translation>
    </message>
    <message>
        <source>Invalid value</source>
        <translation>Valeur non valide</translation>
    </message>
    <message>
        <source>The schedule cannot be built</source>
        <translation>Le planning ne peut pas être construit</translation>
    </message>
    <message>
        <source>Reading or writing failed</source>
        <translation>La lecture ou l’écriture a échoué</translation>
    </message>
    <message>
        <source>Cancelled</source>
        <translation>Annulé</translation>
    </message>
    <message>
        <source>Internal error</source>
        <translation>Erreur interne</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>Erreur</translation>
    </message>
</context>
<context>
    <name>thespis::editor::ScenarioTreeModel</name>
    <message>
        <source>stretch ×%1</source>
        <translation>étirement ×%1</translation>
    </message>
    <message>
        <source>time warp over %1 s</source>
        <translation>distorsion temporelle sur %1 s</translation>
    </message>
    <message>
        <source>loop forever</source>
        <translation>boucle sans fin</translation>
    </message>
    <message numerus="yes">
        <source>loop %n time(s)</source>
        <translation>
            <numerusform>boucle %n fois</numerusform>
            <numerusform>boucle %n fois</numerusform>
        </translation>
    </message>
    <message>
        <source>mirror</source>
        <translation>miroir</translation>
    </message>
    <message>
        <source>move/rotate</source>
        <translation>déplacement/rotation</translation>
    </message>
    <message>
        <source>offset %1 s</source>
        <translation>décalage de %1 s</translation>
    </message>
    <message>
        <source>trim %1–%2 s</source>
        <translation>coupé à %1–%2 s</translation>
    </message>
    <message>
        <source>, peak %1</source>
        <translation>, pic %1</translation>
    </message>
    <message>
        <source>constant %1</source>
        <translation>constante %1</translation>
    </message>
    <message>
        <source>linear fade %1 / %2 s</source>
        <translation>fondu linéaire %1 / %2 s</translation>
    </message>
    <message>
        <source>cubic fade %1 / %2 s</source>
        <translation>fondu cubique %1 / %2 s</translation>
    </message>
    <message>
        <source>linear ADSR %1 / %2 / %3 / %4</source>
        <translation>ADSR linéaire %1 / %2 / %3 / %4</translation>
    </message>
    <message>
        <source>cubic ADSR %1 / %2 / %3 / %4</source>
        <translation>ADSR cubique %1 / %2 / %3 / %4</translation>
    </message>
    <message numerus="yes">
        <source>keyframed, %n key(s)</source>
        <translation>
            <numerusform>par clés, %n clé</numerusform>
            <numerusform>par clés, %n clés</numerusform>
        </translation>
    </message>
    <message>
        <source>normalized</source>
        <translation>normalisé</translation>
    </message>
    <message>
        <source>additive</source>
        <translation>additif</translation>
    </message>
    <message>
        <source>override</source>
        <translation>remplacement</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Nom</translation>
    </message>
    <message>
        <source>Clip</source>
        <translation>Clip</translation>
    </message>
    <message>
        <source>Start (s)</source>
        <translation>Début (s)</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>Mode</translation>
    </message>
    <message>
        <source>Weight curve</source>
        <translation>Courbe de poids</translation>
    </message>
    <message>
        <source>Mask</source>
        <translation>Masque</translation>
    </message>
    <message>
        <source>The motion clip an action plays</source>
        <translation>Le clip de mouvement que joue une action</translation>
    </message>
    <message>
        <source>When the action starts, in seconds from the start of the scenario</source>
        <translation>Quand l’action commence, en secondes depuis le début du scénario</translation>
    </message>
    <message>
        <source>How the action or layer blends with the ones below it</source>
        <translation>Comment l’action ou la couche se mélange à celles du dessous</translation>
    </message>
    <message>
        <source>How the action&apos;s weight rises and falls over its length.
Fades: fade-in / fade-out seconds. ADSR: attack / decay seconds, sustain level, release seconds.</source>
        <translation>Comment le poids de l’action monte et descend sur sa durée.
Fondus : entrée / sortie en secondes. ADSR : attaque / déclin en secondes, niveau de maintien, relâchement en secondes.</translation>
    </message>
    <message>
        <source>Which joints the action moves (empty: the whole body)</source>
        <translation>Les articulations que l’action anime (vide : tout le corps)</translation>
    </message>
    <message numerus="yes">
        <source>%n clip(s)</source>
        <translation>
            <numerusform>%n clip</numerusform>
            <numerusform>%n clips</numerusform>
        </translation>
    </message>
    <message>
        <source>Layer %1</source>
        <translation>Couche %1</translation>
    </message>
    <message>
        <source>face layer</source>
        <translation>couche du visage</translation>
    </message>
    <message>
        <source>body layer</source>
        <translation>couche du corps</translation>
    </message>
    <message>
        <source>base</source>
        <translation>base</translation>
    </message>
    <message>
        <source>Action %1</source>
        <translation>Action %1</translation>
    </message>
    <message>
        <source>whole body</source>
        <translation>tout le corps</translation>
    </message>
    <message>
        <source>Character “%1”: %2 skeleton</source>
        <translation>Personnage « %1 » : squelette %2</translation>
    </message>
    <message>
        <source>The base layer: its actions blend with each other</source>
        <translation>La couche de base : ses actions se mélangent entre elles</translation>
    </message>
    <message>
        <source>Blends %1 over the layers above it</source>
        <translation>Se mélange en mode %1 par-dessus les couches précédentes</translation>
    </message>
    <message>
        <source>Plays clip “%1” from %2 s</source>
        <translation>Joue le clip « %1 » à partir de %2 s</translation>
    </message>
    <message>
        <source>, without end</source>
        <translation>, sans fin</translation>
    </message>
    <message>
        <source> to %1 s</source>
        <translation> jusqu’à %1 s</translation>
    </message>
    <message>
        <source>Weight: %1</source>
        <translation>Poids : %1</translation>
    </message>
    <message>
        <source>Moves: %1</source>
        <translation>Anime : %1</translation>
    </message>
    <message>
        <source>the whole body</source>
        <translation>tout le corps</translation>
    </message>
    <message>
        <source>mask “%1”</source>
        <translation>masque « %1 »</translation>
    </message>
    <message>
        <source>Modifiers: %1</source>
        <translation>Modificateurs : %1</translation>
    </message>
    <message>
        <source>Playing now</source>
        <translation>En cours de lecture</translation>
    </message>
    <message>
        <source>Characters, their animation layers, and the actions in each layer.
A green dot marks an action that plays at the current time.</source>
        <translation>Les personnages, leurs couches d’animation et les actions de chaque couche.
Un point vert signale une action jouée à l’instant courant.</translation>
    </message>
</context>
<context>
    <name>thespis::studio::MainWindow</name>
    <message>
        <source>No scenario is open.
Use File ▸ Open… (Ctrl+O) to open a .thespis file.</source>
        <translation>Aucun scénario ouvert.
Utilisez Fichier ▸ Ouvrir… (Ctrl+O) pour ouvrir un fichier .thespis.</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>&amp;Ouvrir…</translation>
    </message>
    <message>
        <source>Open a scenario file (.thespis)</source>
        <translation>Ouvrir un fichier de scénario (.thespis)</translation>
    </message>
    <message>
        <source>&amp;Reload</source>
        <translation>&amp;Recharger</translation>
    </message>
    <message>
        <source>Read the scenario file again, e.g. after editing it elsewhere</source>
        <translation>Relire le fichier de scénario, par exemple après l’avoir modifié ailleurs</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Quitter</translation>
    </message>
    <message>
        <source>&amp;Play/Pause</source>
        <translation>&amp;Lecture/Pause</translation>
    </message>
    <message>
        <source>Go to &amp;Start</source>
        <translation>Aller au &amp;début</translation>
    </message>
    <message>
        <source>&amp;Loop</source>
        <translation>&amp;Boucle</translation>
    </message>
    <message>
        <source>&amp;Front and Side</source>
        <translation>&amp;Face et profil</translation>
    </message>
    <message>
        <source>F&amp;ront</source>
        <translation>F&amp;ace</translation>
    </message>
    <message>
        <source>&amp;Side</source>
        <translation>&amp;Profil</translation>
    </message>
    <message>
        <source>&amp;About Thespis Studio</source>
        <translation>À &amp;propos de Thespis Studio</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>À propos de &amp;Qt</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Fichier</translation>
    </message>
    <message>
        <source>&amp;Playback</source>
        <translation>&amp;Lecture</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Affichage</translation>
    </message>
    <message>
        <source>Stick figures</source>
        <translation>Figurines</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Aide</translation>
    </message>
    <message>
        <source>Scenario</source>
        <translation>Scénario</translation>
    </message>
    <message>
        <source>Scenario &amp;Outline</source>
        <translation>&amp;Plan du scénario</translation>
    </message>
    <message>
        <source>How often the preview is redrawn</source>
        <translation>Fréquence à laquelle l’aperçu est redessiné</translation>
    </message>
    <message>
        <source>Preview: 000 fps</source>
        <translation>Aperçu : 000 i/s</translation>
    </message>
    <message>
        <source>Could not open “%1”.</source>
        <translation>Impossible d’ouvrir « %1 ».</translation>
    </message>
    <message>
        <source>Could not open %1</source>
        <translation>Impossible d’ouvrir %1</translation>
    </message>
    <message>
        <source>This scenario has no characters yet.</source>
        <translation>Ce scénario n’a pas encore de personnages.</translation>
    </message>
    <message numerus="yes">
        <source>Opened %1: %n character(s)</source>
        <translation>
            <numerusform>%1 ouvert : %n personnage</numerusform>
            <numerusform>%1 ouvert : %n personnages</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>, %n action(s)</source>
        <translation>
            <numerusform>, %n action</numerusform>
            <numerusform>, %n actions</numerusform>
        </translation>
    </message>
    <message>
        <source>, %1 s long. Press Space to play.</source>
        <translation>, %1 s. Espace pour lancer la lecture.</translation>
    </message>
    <message numerus="yes">
        <source>%n warning(s), see the terminal.</source>
        <translation>
            <numerusform>%n avertissement, voir le terminal.</numerusform>
            <numerusform>%n avertissements, voir le terminal.</numerusform>
        </translation>
    </message>
    <message>
        <source>Open Scenario</source>
        <translation>Ouvrir un scénario</translation>
    </message>
    <message>
        <source>Thespis scenarios (*.thespis);;All files (*)</source>
        <translation>Scénarios Thespis (*.thespis);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <source>About Thespis Studio</source>
        <translation>À propos de Thespis Studio</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Thespis Studio %1&lt;/h3&gt;&lt;p&gt;An authoring studio for interactive virtual humans in mixed reality: blending schedules, speech and gestures, precomputed lighting, and AR preview.&lt;/p&gt;&lt;p&gt;Built on the MIRAnim blending engine described by Egges, Papagiannakis and Magnenat-Thalmann, &lt;i&gt;Presence and interaction in mixed reality environments&lt;/i&gt;, The Visual Computer, 2007.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Thespis Studio %1&lt;/h3&gt;&lt;p&gt;Un studio de création d’humains virtuels interactifs en réalité mixte : plannings de mélange, parole et gestes, éclairage précalculé et aperçu en RA.&lt;/p&gt;&lt;p&gt;Fondé sur le moteur de mélange MIRAnim décrit par Egges, Papagiannakis et Magnenat-Thalmann, &lt;i&gt;Presence and interaction in mixed reality environments&lt;/i&gt;, The Visual Computer, 2007.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>&amp;Pause</translation>
    </message>
    <message>
        <source>&amp;Play</source>
        <translation>&amp;Lecture</translation>
    </message>
    <message>
        <source>Paused</source>
        <translation>En pause</translation>
    </message>
    <message>
        <source>Preview: %1 fps</source>
        <translation>Aperçu : %1 i/s</translation>
    </message>
    <message>
        <source>Playing</source>
        <translation>Lecture</translation>
    </message>
    <message>
        <source>Thespis Studio</source>
        <translation>Thespis Studio</translation>
    </message>
    <message>
        <source>%1 — Thespis Studio</source>
        <translation>%1 — Thespis Studio</translation>
    </message>
    <message>
        <source>m</source>
        <comment>metres</comment>
        <translation>m</translation>
    </message>
    <message>
        <source>units</source>
        <comment>length unit of a BVH file</comment>
        <translation>unités</translation>
    </message>
    <message>
        <source>Drag to orbit, right-drag or wheel to zoom, middle-drag to pan, double-click for the home view</source>
        <translation>Glisser pour tourner autour, glisser avec le bouton droit ou la molette pour zoomer, avec le bouton du milieu pour déplacer, double-clic pour la vue initiale</translation>
    </message>
    <message>
        <source>No 3D view: this display offers no OpenGL.
The Skeletons tab shows the animation; thespis-cli render draws the scene headless.</source>
        <translation>Pas de vue 3D : cet affichage n’offre pas OpenGL.
L’onglet Squelettes montre l’animation ; thespis-cli render dessine la scène sans affichage.</translation>
    </message>
    <message>
        <source>Scene</source>
        <translation>Scène</translation>
    </message>
    <message>
        <source>Skeletons</source>
        <translation>Squelettes</translation>
    </message>
    <message>
        <source>&amp;PRT Lighting</source>
        <translation>Éclairage &amp;PRT</translation>
    </message>
    <message>
        <source>P&amp;hong Lighting</source>
        <translation>Éclairage P&amp;hong</translation>
    </message>
    <message>
        <source>&amp;Unlit</source>
        <translation>&amp;Sans éclairage</translation>
    </message>
    <message>
        <source>Precomputed radiance transfer: soft light and self-shadowing from the light probe</source>
        <translation>Transfert de radiance précalculé : lumière douce et ombres propres d’après la sonde de lumière</translation>
    </message>
    <message>
        <source>One directional light and ambient, for comparison with PRT</source>
        <translation>Une lumière directionnelle et une ambiance, pour comparer avec le PRT</translation>
    </message>
    <message>
        <source>&amp;Ground</source>
        <translation>&amp;Sol</translation>
    </message>
    <message>
        <source>&amp;Home View</source>
        <translation>&amp;Vue initiale</translation>
    </message>
    <message>
        <source>The 3D view is empty: %1</source>
        <translation>La vue 3D est vide : %1</translation>
    </message>
</context>
<context>
    <name>thespis::widgets::OsgViewport</name>
    <message>
        <source>No OpenGL context could be created for the 3D view.</source>
        <translation>Aucun contexte OpenGL n’a pu être créé pour la vue 3D.</translation>
    </message>
    <message>
        <source>The 3D view got a core-profile OpenGL context; it needs a compatibility profile.</source>
        <translation>La vue 3D a reçu un contexte OpenGL en profil core ; il lui faut un profil de compatibilité.</translation>
    </message>
    <message>
        <source>The 3D view needs OpenGL 2.1 or newer; this system offers %1.%2.</source>
        <translation>La vue 3D demande OpenGL 2.1 ou plus récent ; ce système offre %1.%2.</translation>
    </message>
</context>
<context>
    <name>thespis::widgets::PoseView</name>
    <message>
        <source>Nothing to show</source>
        <translation>Rien à afficher</translation>
    </message>
    <message>
        <source>Side (from the right)</source>
        <translation>Profil (depuis la droite)</translation>
    </message>
    <message>
        <source>Front</source>
        <translation>Face</translation>
    </message>
</context>
<context>
    <name>thespis::widgets::TransportBar</name>
    <message>
        <source>Go to the start (Home)</source>
        <translation>Aller au début (Début)</translation>
    </message>
    <message>
        <source>Loop</source>
        <translation>Boucle</translation>
    </message>
    <message>
        <source>Start again at the end of the scenario (L)</source>
        <translation>Recommencer à la fin du scénario (L)</translation>
    </message>
    <message>
        <source>Drag to scrub through the scenario</source>
        <translation>Faire glisser pour parcourir le scénario</translation>
    </message>
    <message>
        <source>Current time / length of the scenario (minutes:seconds.milliseconds)</source>
        <translation>Temps actuel / durée du scénario (minutes:secondes.millisecondes)</translation>
    </message>
    <message>
        <source>frame %1</source>
        <translation>image %1</translation>
    </message>
    <message>
        <source>Frame number at %1 frames per second</source>
        <translation>Numéro d’image à %1 images par seconde</translation>
    </message>
    <message>
        <source>Pause (Space)</source>
        <translation>Pause (Espace)</translation>
    </message>
    <message>
        <source>Play (Space)</source>
        <translation>Lecture (Espace)</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Lecture</translation>
    </message>
</context>
</TS>

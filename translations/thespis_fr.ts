<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="fr_FR">
<context>
    <name>CharacterChoice</name>
    <message>
        <source>Character:</source>
        <translation>Personnage :</translation>
    </message>
</context>
<context>
    <name>Microphone</name>
    <message>
        <source>There is no microphone.</source>
        <translation>Il n&apos;y a pas de microphone.</translation>
    </message>
    <message>
        <source>The microphone “%1” did not open (Qt Multimedia error %2).</source>
        <translation>Le microphone « %1 » ne s&apos;est pas ouvert (erreur Qt Multimedia %2).</translation>
    </message>
</context>
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
    <name>thespis::editor::ArCalibrationDialog</name>
    <message>
        <source>Calibrate the Camera</source>
        <translation>Calibrer la caméra</translation>
    </message>
    <message>
        <source>chessboard:COLUMNSxROWS:SQUARE (inner corners, metres) or charuco:DICTIONARY:COLUMNSxROWS:SQUARE:MARKER</source>
        <translation>chessboard:COLONNESxLIGNES:CASE (coins intérieurs, mètres) ou charuco:DICTIONNAIRE:COLONNESxLIGNES:CASE:MARQUEUR</translation>
    </message>
    <message>
        <source>Square pixels (fx = fy)</source>
        <translation>Pixels carrés (fx = fy)</translation>
    </message>
    <message>
        <source>Capture View</source>
        <translation>Capturer la vue</translation>
    </message>
    <message>
        <source>Keep the picture shown as a view of the board; hold the board at many angles</source>
        <translation>Garder l’image affichée comme vue de la mire ; tenir la mire sous de nombreux angles</translation>
    </message>
    <message>
        <source>Add Photos…</source>
        <translation>Ajouter des photos…</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Retirer</translation>
    </message>
    <message>
        <source>Calibrate</source>
        <translation>Calibrer</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Annuler</translation>
    </message>
    <message>
        <source>Not calibrating</source>
        <translation>Aucun calibrage en cours</translation>
    </message>
    <message>
        <source>Save Camera File…</source>
        <translation>Enregistrer le fichier caméra…</translation>
    </message>
    <message>
        <source>Board:</source>
        <translation>Mire :</translation>
    </message>
    <message>
        <source>Views of the board:</source>
        <translation>Vues de la mire :</translation>
    </message>
    <message>
        <source>Choose Photos of the Board</source>
        <translation>Choisir des photos de la mire</translation>
    </message>
    <message>
        <source>Pictures (*.png *.jpg *.jpeg *.bmp *.tif *.tiff)</source>
        <translation>Images (*.png *.jpg *.jpeg *.bmp *.tif *.tiff)</translation>
    </message>
    <message>
        <source>Save the Camera File</source>
        <translation>Enregistrer le fichier caméra</translation>
    </message>
    <message>
        <source>Camera files (*.yml *.yaml *.xml *.json)</source>
        <translation>Fichiers caméra (*.yml *.yaml *.xml *.json)</translation>
    </message>
    <message>
        <source>The camera file could not be written: %1</source>
        <translation>Le fichier caméra n’a pas pu être écrit : %1</translation>
    </message>
    <message>
        <source>No picture</source>
        <translation>Pas d’image</translation>
    </message>
    <message>
        <source>The test pattern shows the board typed here: fix its spec.</source>
        <translation>La mire de test montre la mire saisie ici : corrigez sa description.</translation>
    </message>
    <message>
        <source>No live picture</source>
        <translation>Pas d’image en direct</translation>
    </message>
    <message>
        <source>%1
Add photos of the board instead.</source>
        <translation>%1
Ajoutez plutôt des photos de la mire.</translation>
    </message>
    <message>
        <source>Waiting for the first picture…</source>
        <translation>En attente de la première image…</translation>
    </message>
    <message>
        <source>Hold the board at many angles, filling the picture</source>
        <translation>Tenez la mire sous de nombreux angles, en remplissant l’image</translation>
    </message>
    <message numerus="yes">
        <source>%n view(s) so far</source>
        <translation>
            <numerusform>%n vue pour l’instant</numerusform>
            <numerusform>%n vues pour l’instant</numerusform>
        </translation>
    </message>
    <message>
        <source>Ended</source>
        <translation>Terminé</translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation>Arrêté</translation>
    </message>
    <message>
        <source>The view could not be kept in %1.</source>
        <translation>La vue n’a pas pu être gardée dans %1.</translation>
    </message>
    <message>
        <source>An ArUco grid is for tracking only: calibrate with a chessboard or a ChArUco board.</source>
        <translation>Une grille ArUco ne sert qu’au suivi : calibrez avec un damier ou une mire ChArUco.</translation>
    </message>
    <message numerus="yes">
        <source>Calibrating from %n view(s)…</source>
        <translation>
            <numerusform>Calibrage à partir de %n vue…</numerusform>
            <numerusform>Calibrage à partir de %n vues…</numerusform>
        </translation>
    </message>
    <message>
        <source>Calibrating</source>
        <translation>Calibrage</translation>
    </message>
    <message>
        <source>Finding the board</source>
        <translation>Recherche de la mire</translation>
    </message>
    <message>
        <source>%1: %2 / %3</source>
        <translation>%1 : %2 / %3</translation>
    </message>
    <message>
        <source>%1 — %2 px</source>
        <translation>%1 — %2 px</translation>
    </message>
    <message>
        <source>%1 — found</source>
        <translation>%1 — trouvée</translation>
    </message>
    <message>
        <source>%1 — board not found</source>
        <translation>%1 — mire introuvable</translation>
    </message>
    <message>
        <source>Cancelled</source>
        <translation>Annulé</translation>
    </message>
    <message>
        <source>Failed</source>
        <translation>Échec</translation>
    </message>
    <message>
        <source>Cancelled.</source>
        <translation>Annulé.</translation>
    </message>
    <message>
        <source>Done</source>
        <translation>Terminé</translation>
    </message>
    <message>
        <source>RMS reprojection error %1 px over %2 of %3 views, %4 × %5.
fx %6 ± %7, fy %8 ± %9, centre (%10, %11) px.</source>
        <translation>Erreur de reprojection RMS %1 px sur %2 de %3 vues, %4 × %5.
fx %6 ± %7, fy %8 ± %9, centre (%10, %11) px.</translation>
    </message>
    <message>
        <source>Calibrate first.</source>
        <translation>Calibrez d’abord.</translation>
    </message>
    <message>
        <source>At least %1 views of the board are needed</source>
        <translation>Il faut au moins %1 vues de la mire</translation>
    </message>
</context>
<context>
    <name>thespis::editor::ArPreviewPanel</name>
    <message>
        <source>Test pattern (a synthetic board)</source>
        <translation>Mire de test (synthétique)</translation>
    </message>
    <message>
        <source>Video file</source>
        <translation>Fichier vidéo</translation>
    </message>
    <message>
        <source>Folder of pictures</source>
        <translation>Dossier d’images</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>Caméra</translation>
    </message>
    <message>
        <source>A board moving as if hand-held, seen by a known camera: nothing to print or calibrate. It shows the target&apos;s board.</source>
        <translation>Une mire qui bouge comme tenue à la main, vue par une caméra connue : rien à imprimer ni à calibrer. Elle montre la mire de la cible.</translation>
    </message>
    <message>
        <source>No video chosen</source>
        <translation>Aucune vidéo choisie</translation>
    </message>
    <message>
        <source>Choose…</source>
        <translation>Choisir…</translation>
    </message>
    <message>
        <source>Choose a Video</source>
        <translation>Choisir une vidéo</translation>
    </message>
    <message>
        <source>Videos (*.mp4 *.avi *.mov *.mkv *.webm);;All files (*)</source>
        <translation>Vidéos (*.mp4 *.avi *.mov *.mkv *.webm);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <source>No folder chosen</source>
        <translation>Aucun dossier choisi</translation>
    </message>
    <message>
        <source> fps</source>
        <translation> i/s</translation>
    </message>
    <message>
        <source>How many pictures a second the folder plays</source>
        <translation>Combien d’images par seconde le dossier joue</translation>
    </message>
    <message>
        <source>Choose a Folder of Pictures</source>
        <translation>Choisir un dossier d’images</translation>
    </message>
    <message>
        <source>Rescan</source>
        <translation>Rechercher</translation>
    </message>
    <message>
        <source>Look for cameras again (after plugging one in)</source>
        <translation>Chercher à nouveau des caméras (après en avoir branché une)</translation>
    </message>
    <message>
        <source>No camera file chosen</source>
        <translation>Aucun fichier caméra choisi</translation>
    </message>
    <message>
        <source>The camera&apos;s intrinsics as OpenCV writes them (.yml, .yaml, .xml, .json)</source>
        <translation>Les paramètres intrinsèques de la caméra, tels qu’OpenCV les écrit (.yml, .yaml, .xml, .json)</translation>
    </message>
    <message>
        <source>Calibrate…</source>
        <translation>Calibrer…</translation>
    </message>
    <message>
        <source>Calibrate the camera from views of a chessboard or a ChArUco board</source>
        <translation>Calibrer la caméra à partir de vues d’un damier ou d’une mire ChArUco</translation>
    </message>
    <message>
        <source>Choose a Camera File</source>
        <translation>Choisir un fichier caméra</translation>
    </message>
    <message>
        <source>Camera files (*.yml *.yaml *.xml *.json);;All files (*)</source>
        <translation>Fichiers caméra (*.yml *.yaml *.xml *.json);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <source>Board:</source>
        <translation>Mire :</translation>
    </message>
    <message>
        <source>Picture:</source>
        <translation>Image :</translation>
    </message>
    <message>
        <source>aruco-grid:DICTIONARY:COLUMNSxROWS:MARKER:GAP or charuco:DICTIONARY:COLUMNSxROWS:SQUARE:MARKER, lengths in metres</source>
        <translation>aruco-grid:DICTIONNAIRE:COLONNESxLIGNES:MARQUEUR:ÉCART ou charuco:DICTIONNAIRE:COLONNESxLIGNES:CASE:MARQUEUR, longueurs en mètres</translation>
    </message>
    <message>
        <source>A printed picture (PNG, JPEG)</source>
        <translation>Une image imprimée (PNG, JPEG)</translation>
    </message>
    <message>
        <source> m wide</source>
        <translation> m de large</translation>
    </message>
    <message>
        <source>Printed:</source>
        <translation>Imprimée :</translation>
    </message>
    <message>
        <source>Choose the Printed Picture</source>
        <translation>Choisir l’image imprimée</translation>
    </message>
    <message>
        <source>Pictures (*.png *.jpg *.jpeg *.bmp)</source>
        <translation>Images (*.png *.jpg *.jpeg *.bmp)</translation>
    </message>
    <message>
        <source>Of life size: 0.1 stands a 1.8 m character 18 cm tall on a desk</source>
        <translation>De la taille réelle : 0,1 pose un personnage de 1,8 m haut de 18 cm sur un bureau</translation>
    </message>
    <message>
        <source>How far the world turns about the target&apos;s normal</source>
        <translation>De combien le monde tourne autour de la normale de la cible</translation>
    </message>
    <message>
        <source> m</source>
        <translation> m</translation>
    </message>
    <message>
        <source>Where the world&apos;s origin is on the target, from its centre along its own axes</source>
        <translation>Où l’origine du monde se trouve sur la cible, depuis son centre le long de ses propres axes</translation>
    </message>
    <message>
        <source>Shadows on the real ground</source>
        <translation>Ombres sur le sol réel</translation>
    </message>
    <message>
        <source>Scale:</source>
        <translation>Échelle :</translation>
    </message>
    <message>
        <source>Heading:</source>
        <translation>Orientation :</translation>
    </message>
    <message>
        <source>Offset:</source>
        <translation>Décalage :</translation>
    </message>
    <message>
        <source>Show AR Shadows</source>
        <translation>Afficher les ombres RA</translation>
    </message>
    <message>
        <source>Hide AR Shadows</source>
        <translation>Masquer les ombres RA</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>No camera found</source>
        <translation>Aucune caméra trouvée</translation>
    </message>
    <message>
        <source>No camera found: plug one in and press Rescan, or choose a video file or the test pattern.</source>
        <translation>Aucune caméra trouvée : branchez-en une et cliquez sur « Rechercher », ou choisissez un fichier vidéo ou la mire de test.</translation>
    </message>
    <message>
        <source>Choose a video file.</source>
        <translation>Choisissez un fichier vidéo.</translation>
    </message>
    <message>
        <source>Choose a folder of pictures.</source>
        <translation>Choisissez un dossier d’images.</translation>
    </message>
    <message>
        <source>, %1 fps</source>
        <translation>, %1 i/s</translation>
    </message>
    <message>
        <source>, %1 frames (%2 s)</source>
        <translation>, %1 images (%2 s)</translation>
    </message>
    <message>
        <source>, %1 frames</source>
        <translation>, %1 images</translation>
    </message>
    <message>
        <source>This camera file cannot be used: %1</source>
        <translation>Ce fichier caméra est inutilisable : %1</translation>
    </message>
    <message>
        <source>The test pattern&apos;s camera is known exactly: no file needed.</source>
        <translation>La caméra de la mire de test est connue exactement : aucun fichier nécessaire.</translation>
    </message>
    <message>
        <source>The camera file is for %1 pictures, but the source gives %2: calibrate the camera at the size it films at.</source>
        <translation>Le fichier caméra est pour des images de %1, mais la source donne %2 : calibrez la caméra à la taille à laquelle elle filme.</translation>
    </message>
    <message>
        <source>%1, fx %2 px</source>
        <translation>%1, fx %2 px</translation>
    </message>
    <message>
        <source>, RMS %1 px</source>
        <translation>, RMS %1 px</translation>
    </message>
    <message>
        <source>Choose the camera file of the camera that filmed it, or calibrate one.</source>
        <translation>Choisissez le fichier de la caméra qui l’a filmé, ou calibrez-en une.</translation>
    </message>
    <message>
        <source>The board spec does not parse: %1</source>
        <translation>La description de la mire est invalide : %1</translation>
    </message>
    <message>
        <source>A chessboard calibrates a camera but cannot be tracked: use an ArUco grid or a ChArUco board.</source>
        <translation>Un damier calibre une caméra mais ne peut pas être suivi : utilisez une grille ArUco ou une mire ChArUco.</translation>
    </message>
    <message>
        <source>ArUco grid, %1 × %2 markers of %3 cm, %4 × %5 cm in all</source>
        <translation>Grille ArUco, %1 × %2 marqueurs de %3 cm, %4 × %5 cm en tout</translation>
    </message>
    <message>
        <source>ChArUco board, %1 × %2 squares of %3 cm</source>
        <translation>Mire ChArUco, %1 × %2 cases de %3 cm</translation>
    </message>
    <message>
        <source>Choose the printed picture to track.</source>
        <translation>Choisissez l’image imprimée à suivre.</translation>
    </message>
    <message>
        <source>%1: no such picture.</source>
        <translation>%1 : image introuvable.</translation>
    </message>
    <message>
        <source>The test pattern shows a board: track a board with it.</source>
        <translation>La mire de test montre une mire : suivez une mire avec elle.</translation>
    </message>
    <message>
        <source>%1, %2 m wide</source>
        <translation>%1, %2 m de large</translation>
    </message>
    <message>
        <source>Source</source>
        <translation>Source</translation>
    </message>
    <message>
        <source>Target</source>
        <translation>Cible</translation>
    </message>
    <message>
        <source>Placement on the Target</source>
        <translation>Placement sur la cible</translation>
    </message>
    <message>
        <source>Preview</source>
        <translation>Aperçu</translation>
    </message>
    <message>
        <source>Light from a mirror ball in view</source>
        <translation>Lumière d’une boule miroir visible</translation>
    </message>
    <message>
        <source>Find a chrome ball in the picture and light the characters with what it mirrors</source>
        <translation>Trouver une boule chromée dans l’image et éclairer les personnages avec ce qu’elle reflète</translation>
    </message>
    <message>
        <source>Smooth edges (slower)</source>
        <translation>Bords lissés (plus lent)</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Démarrer</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Arrêter</translation>
    </message>
    <message>
        <source>Record…</source>
        <translation>Enregistrer…</translation>
    </message>
    <message>
        <source>Write what the preview shows to a video (.mp4 or .avi)</source>
        <translation>Écrire ce que montre l’aperçu dans une vidéo (.mp4 ou .avi)</translation>
    </message>
    <message>
        <source>Record the AR Preview</source>
        <translation>Enregistrer l’aperçu RA</translation>
    </message>
    <message>
        <source>Videos (*.mp4 *.avi)</source>
        <translation>Vidéos (*.mp4 *.avi)</translation>
    </message>
    <message>
        <source>Place the World on the Target</source>
        <translation>Placer le monde sur la cible</translation>
    </message>
    <message>
        <source>Cannot start</source>
        <translation>Démarrage impossible</translation>
    </message>
    <message>
        <source>Starting…</source>
        <translation>Démarrage…</translation>
    </message>
    <message>
        <source>Reading the first frames and preparing the scene.</source>
        <translation>Lecture des premières images et préparation de la scène.</translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation>Arrêté</translation>
    </message>
    <message>
        <source>Press Start to go on.</source>
        <translation>Cliquez sur « Démarrer » pour continuer.</translation>
    </message>
    <message>
        <source>%1 fps</source>
        <translation>%1 i/s</translation>
    </message>
    <message>
        <source>latency %1 ms</source>
        <translation>latence %1 ms</translation>
    </message>
    <message numerus="yes">
        <source>Tracking: %n feature(s)</source>
        <translation>
            <numerusform>Suivi : %n repère</numerusform>
            <numerusform>Suivi : %n repères</numerusform>
        </translation>
    </message>
    <message>
        <source>Target lost: holding its last place</source>
        <translation>Cible perdue : dernière position conservée</translation>
    </message>
    <message>
        <source>Searching for the target…</source>
        <translation>Recherche de la cible…</translation>
    </message>
    <message>
        <source>frame %1</source>
        <translation>image %1</translation>
    </message>
    <message>
        <source>dropped: %1</source>
        <translation>perdues : %1</translation>
    </message>
    <message>
        <source>lit by the mirror ball</source>
        <translation>éclairé par la boule miroir</translation>
    </message>
    <message>
        <source>REC</source>
        <translation>REC</translation>
    </message>
    <message>
        <source>Ended</source>
        <translation>Terminé</translation>
    </message>
    <message>
        <source>%1.
Press Start to play it again.</source>
        <translation>%1.
Cliquez sur « Démarrer » pour la rejouer.</translation>
    </message>
    <message>
        <source>Stopped by a problem</source>
        <translation>Arrêté par un problème</translation>
    </message>
    <message>
        <source>%1
Fix it, then press Start.</source>
        <translation>%1
Corrigez-le, puis cliquez sur « Démarrer ».</translation>
    </message>
    <message>
        <source>Recorded to %1.</source>
        <translation>Enregistré dans %1.</translation>
    </message>
    <message>
        <source>Start the preview first, then record it.</source>
        <translation>Démarrez d’abord l’aperçu, puis enregistrez-le.</translation>
    </message>
    <message>
        <source>Cannot record: %1</source>
        <translation>Enregistrement impossible : %1</translation>
    </message>
    <message>
        <source>Recording to %1…</source>
        <translation>Enregistrement dans %1…</translation>
    </message>
    <message>
        <source>The recording could not be finished: %1</source>
        <translation>L’enregistrement n’a pas pu être terminé : %1</translation>
    </message>
    <message>
        <source>Play the scenario over the video</source>
        <translation>Jouer le scénario sur la vidéo</translation>
    </message>
    <message>
        <source>Stop Recording</source>
        <translation>Arrêter l’enregistrement</translation>
    </message>
    <message>
        <source>AR Preview</source>
        <translation>Aperçu RA</translation>
    </message>
    <message>
        <source>Press Start to play the scenario over the video.</source>
        <translation>Cliquez sur « Démarrer » pour jouer le scénario sur la vidéo.</translation>
    </message>
    <message>
        <source>mirror ball: %1</source>
        <translation>boule miroir : %1</translation>
    </message>
    <message>
        <source>Mirror ball</source>
        <translation>Boule miroir</translation>
    </message>
    <message>
        <source>The picture size asked of the camera; its camera file must be for the same size</source>
        <translation>La taille d’image demandée à la caméra ; son fichier de caméra doit être pour la même taille</translation>
    </message>
    <message>
        <source>Camera file&apos;s size</source>
        <translation>Taille du fichier de caméra</translation>
    </message>
    <message>
        <source>Frames a second asked of the camera (it may give fewer in dim light)</source>
        <translation>Images par seconde demandées à la caméra (elle peut en donner moins en faible lumière)</translation>
    </message>
    <message>
        <source>The camera file&apos;s size is asked for, at %1 fps.</source>
        <translation>La taille du fichier de caméra est demandée, à %1 i/s.</translation>
    </message>
    <message>
        <source>Plays with the studio&apos;s transport</source>
        <translation>Joue avec la barre de transport du studio</translation>
    </message>
    <message>
        <source>Plays on the video&apos;s time</source>
        <translation>Joue au temps de la vidéo</translation>
    </message>
    <message>
        <source>The transport: play, scrub and loop in the studio, and the video shows it. The video&apos;s time: the playhead follows the video frame by frame, as a recording would.</source>
        <translation>La barre de transport : lecture, défilement et boucle dans le studio, et la vidéo le montre. Le temps de la vidéo : la tête de lecture suit la vidéo image par image, comme un enregistrement.</translation>
    </message>
    <message>
        <source>The characters changed, which ended the recording.
Press Start to see them over the video.</source>
        <translation>Les personnages ont changé, ce qui a arrêté l&apos;enregistrement.
Appuyez sur Démarrer pour les voir sur la vidéo.</translation>
    </message>
    <message>
        <source>The characters changed: the preview started again with them.</source>
        <translation>Les personnages ont changé : l&apos;aperçu a redémarré avec eux.</translation>
    </message>
    <message>
        <source>motion blur %1 px</source>
        <translation>flou de bougé %1 px</translation>
    </message>
    <message>
        <source>tilt unsure (ratio %1)</source>
        <translation>inclinaison incertaine (rapport %1)</translation>
    </message>
    <message>
        <source>Characters look at the camera</source>
        <translation>Les personnages regardent la caméra</translation>
    </message>
    <message>
        <source>Their eyes, heads and chests turn to the real camera as it is tracked: they look at the visitor</source>
        <translation>Leurs yeux, leur tête et leur buste se tournent vers la vraie caméra suivie : ils regardent le visiteur</translation>
    </message>
</context>
<context>
    <name>thespis::editor::Autosaver</name>
    <message>
        <source>Autosave failed: %1</source>
        <translation>Échec de l’enregistrement automatique : %1</translation>
    </message>
</context>
<context>
    <name>thespis::editor::BakePanel</name>
    <message>
        <source>The character whose body is baked</source>
        <translation>Le personnage dont le corps est précalculé</translation>
    </message>
    <message>
        <source>Character:</source>
        <translation>Personnage :</translation>
    </message>
    <message>
        <source>Uses now:</source>
        <translation>Utilise actuellement :</translation>
    </message>
    <message>
        <source>Bake Settings</source>
        <translation>Paramètres du précalcul</translation>
    </message>
    <message>
        <source>Diffuse unshadowed</source>
        <translation>Diffus sans ombres</translation>
    </message>
    <message>
        <source>Diffuse shadowed</source>
        <translation>Diffus avec ombres</translation>
    </message>
    <message>
        <source>Diffuse shadowed merged (paper)</source>
        <translation>Diffus avec ombres fusionné (article)</translation>
    </message>
    <message>
        <source>DU: no shadows at all</source>
        <translation>DU : aucune ombre</translation>
    </message>
    <message>
        <source>DS: each segment shadows only itself</source>
        <translation>DS : chaque segment ne projette d’ombre que sur lui-même</translation>
    </message>
    <message>
        <source>DSM: every segment shadows the others; receivers are transparent, occluders are not baked</source>
        <translation>DSM : chaque segment projette des ombres sur les autres ; les récepteurs sont transparents, les occulteurs ne sont pas précalculés</translation>
    </message>
    <message>
        <source>Transfer:</source>
        <translation>Transfert :</translation>
    </message>
    <message>
        <source>Spherical harmonics order: bands 0 … order − 1</source>
        <translation>Ordre des harmoniques sphériques : bandes 0 … ordre − 1</translation>
    </message>
    <message>
        <source>SH order:</source>
        <translation>Ordre SH :</translation>
    </message>
    <message>
        <source>Stratified cosine-weighted directions traced from every vertex</source>
        <translation>Directions stratifiées pondérées par le cosinus, tracées depuis chaque sommet</translation>
    </message>
    <message>
        <source>Rays per vertex:</source>
        <translation>Rayons par sommet :</translation>
    </message>
    <message>
        <source>Embree</source>
        <translation>Embree</translation>
    </message>
    <message>
        <source>Uniform grid</source>
        <translation>Grille uniforme</translation>
    </message>
    <message>
        <source>The ray tracer: Embree, or the paper&apos;s uniform grid (same results, slower)</source>
        <translation>Le lancer de rayons : Embree, ou la grille uniforme de l’article (mêmes résultats, plus lent)</translation>
    </message>
    <message>
        <source>Ray tracer:</source>
        <translation>Lancer de rayons :</translation>
    </message>
    <message>
        <source>Relaxation ε in metres: hits nearer than this are ignored (default 1.71e-4, the H-Anim segment gap)</source>
        <translation>Relaxation ε en mètres : les impacts plus proches sont ignorés (par défaut 1.71e-4, l’écart entre segments H-Anim)</translation>
    </message>
    <message>
        <source>Relaxation ε (m):</source>
        <translation>Relaxation ε (m) :</translation>
    </message>
    <message>
        <source>All (%1)</source>
        <translation>Tous (%1)</translation>
    </message>
    <message>
        <source>Worker threads; the result does not depend on it</source>
        <translation>Threads de calcul ; le résultat n’en dépend pas</translation>
    </message>
    <message>
        <source>Threads:</source>
        <translation>Threads :</translation>
    </message>
    <message>
        <source>Start Bake</source>
        <translation>Lancer le précalcul</translation>
    </message>
    <message>
        <source>Bake the character in the background; the result is one undoable step</source>
        <translation>Précalculer le personnage en arrière-plan ; le résultat forme une seule étape annulable</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Annuler</translation>
    </message>
    <message>
        <source>Stop the bake; nothing changes</source>
        <translation>Arrêter le précalcul ; rien n’est modifié</translation>
    </message>
    <message>
        <source>Not baking</source>
        <translation>Aucun précalcul en cours</translation>
    </message>
    <message>
        <source>Show PRT lighting (off: Phong)</source>
        <translation>Afficher l’éclairage PRT (désactivé : Phong)</translation>
    </message>
    <message>
        <source>Shade the viewport with the baked transfer, or with plain Phong to compare</source>
        <translation>Ombrer la vue 3D avec le transfert précalculé, ou avec un simple Phong pour comparer</translation>
    </message>
    <message>
        <source>%1 coefficients per vertex</source>
        <translation>%1 coefficients par sommet</translation>
    </message>
    <message>
        <source>Relaxation ε must be a distance in metres from 0 to %1 (for example 1.71e-4), not “%2”.</source>
        <translation>La relaxation ε doit être une distance en mètres de 0 à %1 (par exemple 1.71e-4), et non « %2 ».</translation>
    </message>
    <message>
        <source>There is no character to bake.</source>
        <translation>Il n’y a aucun personnage à précalculer.</translation>
    </message>
    <message>
        <source>Save the scenario in a folder you can write to first: the bake goes to %1, which cannot be written.</source>
        <translation>Enregistrez d’abord le scénario dans un dossier accessible en écriture : le précalcul est écrit dans %1, qui n’est pas accessible en écriture.</translation>
    </message>
    <message>
        <source>its folder</source>
        <translation>son dossier</translation>
    </message>
    <message>
        <source>The body of the character could not be loaded: %1</source>
        <translation>Le corps du personnage n’a pas pu être chargé : %1</translation>
    </message>
    <message>
        <source>Baking %1: %2, order %3, %4 rays per vertex…</source>
        <translation>Précalcul de %1 : %2, ordre %3, %4 rayons par sommet…</translation>
    </message>
    <message>
        <source>%p% — %1 / %2 vertices</source>
        <translation>%p% — %1 / %2 sommets</translation>
    </message>
    <message>
        <source>Cancelled</source>
        <translation>Annulé</translation>
    </message>
    <message>
        <source>Cancelled — nothing changed.</source>
        <translation>Annulé — rien n’a été modifié.</translation>
    </message>
    <message>
        <source>Failed</source>
        <translation>Échec</translation>
    </message>
    <message>
        <source>The bake failed: %1</source>
        <translation>Le précalcul a échoué : %1</translation>
    </message>
    <message>
        <source>The scenario was closed while baking; nothing changed.</source>
        <translation>Le scénario a été fermé pendant le précalcul ; rien n’a été modifié.</translation>
    </message>
    <message>
        <source>The character “%1” is gone; the bake was thrown away.</source>
        <translation>Le personnage « %1 » n’existe plus ; le précalcul a été abandonné.</translation>
    </message>
    <message>
        <source>%1 changed while baking (body or segment tags); nothing changed: bake again.</source>
        <translation>%1 a changé pendant le précalcul (corps ou étiquettes de segments) ; rien n’a été modifié : relancez le précalcul.</translation>
    </message>
    <message>
        <source>Bake %1 (%2, order %3)</source>
        <translation>Précalculer %1 (%2, ordre %3)</translation>
    </message>
    <message>
        <source>The bake could not be applied: %1</source>
        <translation>Le précalcul n’a pas pu être appliqué : %1</translation>
    </message>
    <message>
        <source>Last bake: %1, order %2, %3 rays per vertex — %4 s, %5 Mrays/s.</source>
        <translation>Dernier précalcul : %1, ordre %2, %3 rayons par sommet — %4 s, %5 Mrayons/s.</translation>
    </message>
    <message>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <source>none — unshadowed (DU)</source>
        <translation>aucun — sans ombres (DU)</translation>
    </message>
    <message>
        <source>Bake the character to light it with shadows</source>
        <translation>Précalculez le personnage pour l’éclairer avec des ombres</translation>
    </message>
    <message>
        <source>%1
missing or unreadable — lit unshadowed (DU)</source>
        <translation>%1
manquant ou illisible — éclairé sans ombres (DU)</translation>
    </message>
    <message>
        <source>%1
stale: it no longer fits the body or its segment tags — lit unshadowed (DU) until baked again</source>
        <translation>%1
obsolète : ne correspond plus au corps ou à ses étiquettes de segments — éclairé sans ombres (DU) jusqu’au prochain précalcul</translation>
    </message>
    <message>
        <source>%1
%2, order %3, %4 rays per vertex</source>
        <translation>%1
%2, ordre %3, %4 rayons par sommet</translation>
    </message>
</context>
<context>
    <name>thespis::editor::BlinkProperties</name>
    <message>
        <source>Blinks</source>
        <translation>Clignements</translation>
    </message>
    <message>
        <source> a minute</source>
        <translation> par minute</translation>
    </message>
    <message>
        <source>How often the eyes blink on average: about 17 a minute at rest, 26 in conversation</source>
        <translation>Fréquence moyenne des clignements : environ 17 par minute au repos, 26 en conversation</translation>
    </message>
    <message>
        <source>At rest</source>
        <translation>Au repos</translation>
    </message>
    <message>
        <source>17 blinks a minute, as measured at rest</source>
        <translation>17 clignements par minute, comme mesuré au repos</translation>
    </message>
    <message>
        <source>Talking</source>
        <translation>En conversation</translation>
    </message>
    <message>
        <source>26 blinks a minute, as measured in conversation</source>
        <translation>26 clignements par minute, comme mesuré en conversation</translation>
    </message>
    <message>
        <source>Which random intervals the blinks follow: two characters with different seeds do not blink together</source>
        <translation>Quels intervalles aléatoires suivent les clignements : deux personnages de graines différentes ne clignent pas ensemble</translation>
    </message>
    <message>
        <source>A whole blink takes less than 400 ms.</source>
        <translation>Un clignement entier dure moins de 400 ms.</translation>
    </message>
    <message>
        <source>How long the lids take to close (about 100 ms). %1</source>
        <translation>Durée de fermeture des paupières (environ 100 ms). %1</translation>
    </message>
    <message>
        <source>How long the eyes stay shut. %1</source>
        <translation>Durée pendant laquelle les yeux restent fermés. %1</translation>
    </message>
    <message>
        <source>How long the lids take to open again (slower than closing). %1</source>
        <translation>Durée de réouverture des paupières (plus lente que la fermeture). %1</translation>
    </message>
    <message>
        <source>Rate:</source>
        <translation>Fréquence :</translation>
    </message>
    <message>
        <source>Seed:</source>
        <translation>Graine :</translation>
    </message>
    <message>
        <source>Closing:</source>
        <translation>Fermeture :</translation>
    </message>
    <message>
        <source>Shut:</source>
        <translation>Fermés :</translation>
    </message>
    <message>
        <source>Opening:</source>
        <translation>Ouverture :</translation>
    </message>
    <message>
        <source>Change Blink Rate</source>
        <translation>Modifier la fréquence des clignements</translation>
    </message>
    <message>
        <source>Change Blink Seed</source>
        <translation>Modifier la graine des clignements</translation>
    </message>
    <message>
        <source>Change Blink Timing</source>
        <translation>Modifier la durée des clignements</translation>
    </message>
    <message>
        <source>Blinks (clip &quot;%1&quot;, shared by its actions)</source>
        <translation>Clignements (clip « %1 », partagé par ses actions)</translation>
    </message>
</context>
<context>
    <name>thespis::editor::BmlLexiconBox</name>
    <message>
        <source>BML lexemes</source>
        <translation>Lexèmes BML</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Ajouter</translation>
    </message>
    <message>
        <source>Add a lexeme playing the character&apos;s first gesture</source>
        <translation>Ajouter un lexème jouant le premier geste du personnage</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Supprimer</translation>
    </message>
    <message>
        <source>Remove the selected lexeme</source>
        <translation>Supprimer le lexème sélectionné</translation>
    </message>
    <message>
        <source>Reset to Defaults</source>
        <translation>Rétablir les valeurs par défaut</translation>
    </message>
    <message>
        <source>Give the character the default lexemes again (BEAT, NOD and AGREE: agree; WAVE and GREET: greet; POINT: point)</source>
        <translation>Redonner au personnage les lexèmes par défaut (BEAT, NOD et AGREE : agree ; WAVE et GREET : greet ; POINT : point)</translation>
    </message>
    <message>
        <source>Add BML Lexeme</source>
        <translation>Ajouter un lexème BML</translation>
    </message>
    <message>
        <source>Remove BML Lexeme</source>
        <translation>Supprimer un lexème BML</translation>
    </message>
    <message>
        <source>Reset BML Lexemes</source>
        <translation>Rétablir les lexèmes BML</translation>
    </message>
    <message>
        <source>(the character&apos;s own)</source>
        <translation>(propres au personnage)</translation>
    </message>
    <message>
        <source>(the defaults)</source>
        <translation>(par défaut)</translation>
    </message>
</context>
<context>
    <name>thespis::editor::BmlLexiconModel</name>
    <message>
        <source>The character has no gesture named “%1”: BML&apos;s %2 plays no gesture through this row.</source>
        <translation>Le personnage n’a pas de geste nommé « %1 » : le %2 de BML ne joue aucun geste par cette ligne.</translation>
    </message>
    <message>
        <source>Lexeme</source>
        <translation>Lexème</translation>
    </message>
    <message>
        <source>Gesture</source>
        <translation>Geste</translation>
    </message>
    <message>
        <source>Rename BML Lexeme</source>
        <translation>Renommer un lexème BML</translation>
    </message>
    <message>
        <source>Set BML Lexeme</source>
        <translation>Définir un lexème BML</translation>
    </message>
</context>
<context>
    <name>thespis::editor::CharacterDialog</name>
    <message>
        <source>Add Character</source>
        <translation>Ajouter un personnage</translation>
    </message>
    <message>
        <source>The built-in humanoid</source>
        <translation>L’humanoïde intégré</translation>
    </message>
    <message>
        <source>H-Anim LOA 1 (18 joints)</source>
        <translation>H-Anim LOA 1 (18 articulations)</translation>
    </message>
    <message>
        <source>H-Anim, the paper&apos;s 25 joints (spine, neck, clavicles)</source>
        <translation>H-Anim, les 25 articulations de l’article (colonne, cou, clavicules)</translation>
    </message>
    <message>
        <source>H-Anim LOA 2 (71 joints, with fingers)</source>
        <translation>H-Anim LOA 2 (71 articulations, avec les doigts)</translation>
    </message>
    <message>
        <source>A glTF model</source>
        <translation>Un modèle glTF</translation>
    </message>
    <message>
        <source>No model chosen.</source>
        <translation>Aucun modèle choisi.</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>Parcourir…</translation>
    </message>
    <message>
        <source>Name:</source>
        <translation>Nom :</translation>
    </message>
    <message>
        <source>Choose a glTF Model</source>
        <translation>Choisir un modèle glTF</translation>
    </message>
    <message>
        <source>glTF models (*.gltf *.glb)</source>
        <translation>Modèles glTF (*.gltf *.glb)</translation>
    </message>
    <message>
        <source>%1 cannot be used: %2</source>
        <translation>Impossible d’utiliser %1 : %2</translation>
    </message>
    <message>
        <source>Actor</source>
        <translation>Acteur</translation>
    </message>
    <message numerus="yes">
        <source>Import its %n animation(s) as clips</source>
        <translation>
            <numerusform>Importer %n animation du modèle comme clip</numerusform>
            <numerusform>Importer les %n animations du modèle comme clips</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>thespis::editor::CharacterProperties</name>
    <message>
        <source>Choose Model…</source>
        <translation>Choisir un modèle…</translation>
    </message>
    <message>
        <source>Built-in Humanoid</source>
        <translation>Humanoïde intégré</translation>
    </message>
    <message>
        <source> m</source>
        <translation> m</translation>
    </message>
    <message>
        <source>Which way the character faces: 0° looks along +Z, 90° along +X</source>
        <translation>Orientation du personnage : à 0° il regarde vers +Z, à 90° vers +X</translation>
    </message>
    <message>
        <source>Character:</source>
        <translation>Personnage :</translation>
    </message>
    <message>
        <source>Body:</source>
        <translation>Corps :</translation>
    </message>
    <message>
        <source>Motion plays on:</source>
        <translation>Mouvement joué sur :</translation>
    </message>
    <message>
        <source>Stands at:</source>
        <translation>Placé en :</translation>
    </message>
    <message>
        <source>Faces:</source>
        <translation>Orientation :</translation>
    </message>
    <message>
        <source>Has:</source>
        <translation>Contient :</translation>
    </message>
    <message>
        <source>Rename Character</source>
        <translation>Renommer le personnage</translation>
    </message>
    <message>
        <source>Change Skeleton</source>
        <translation>Modifier le squelette</translation>
    </message>
    <message>
        <source>Use the Built-in Humanoid</source>
        <translation>Utiliser l’humanoïde intégré</translation>
    </message>
    <message>
        <source>Choose a glTF Model</source>
        <translation>Choisir un modèle glTF</translation>
    </message>
    <message>
        <source>glTF models (*.gltf *.glb)</source>
        <translation>Modèles glTF (*.gltf *.glb)</translation>
    </message>
    <message>
        <source>Change Model</source>
        <translation>Modifier le modèle</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1 : %2</translation>
    </message>
    <message>
        <source>Move Character</source>
        <translation>Déplacer le personnage</translation>
    </message>
    <message>
        <source>The built-in humanoid</source>
        <translation>L’humanoïde intégré</translation>
    </message>
    <message>
        <source>H-Anim LOA 1 (18 joints)</source>
        <translation>H-Anim LOA 1 (18 articulations)</translation>
    </message>
    <message>
        <source>H-Anim, the paper&apos;s 25 joints</source>
        <translation>H-Anim, les 25 articulations de l’article</translation>
    </message>
    <message>
        <source>H-Anim LOA 2 (71 joints)</source>
        <translation>H-Anim LOA 2 (71 articulations)</translation>
    </message>
    <message>
        <source>The model&apos;s own rig</source>
        <translation>Le rig propre au modèle</translation>
    </message>
    <message>
        <source>The skeleton of clip %1</source>
        <translation>Le squelette du clip %1</translation>
    </message>
    <message>
        <source>%1, %2, %3</source>
        <translation>%1, %2, %3</translation>
    </message>
    <message numerus="yes">
        <source>%n layer(s)</source>
        <translation>
            <numerusform>%n couche</numerusform>
            <numerusform>%n couches</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n clip(s)</source>
        <translation>
            <numerusform>%n clip</numerusform>
            <numerusform>%n clips</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n action(s)</source>
        <translation>
            <numerusform>%n action</numerusform>
            <numerusform>%n actions</numerusform>
        </translation>
    </message>
    <message>
        <source>Choose…</source>
        <translation>Choisir…</translation>
    </message>
    <message>
        <source>Use a face mapping table file (thespis-cli face-mapping --save-mapping writes one)</source>
        <translation>Utiliser un fichier de table de correspondance du visage (thespis-cli face-mapping --save-mapping en écrit une)</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>Automatique</translation>
    </message>
    <message>
        <source>Drive the face by the table recognised from the model&apos;s names</source>
        <translation>Animer le visage par la table reconnue d&apos;après les noms du modèle</translation>
    </message>
    <message>
        <source>Edit…</source>
        <translation>Modifier…</translation>
    </message>
    <message>
        <source>Face mapping:</source>
        <translation>Correspondance du visage :</translation>
    </message>
    <message>
        <source>Choose a Face Mapping Table</source>
        <translation>Choisir une table de correspondance du visage</translation>
    </message>
    <message>
        <source>Use the Recognised Face Mapping</source>
        <translation>Utiliser la correspondance du visage reconnue</translation>
    </message>
    <message>
        <source>Choose Face Mapping</source>
        <translation>Choisir la correspondance du visage</translation>
    </message>
    <message>
        <source>Edit Face Mapping: %1</source>
        <translation>Modifier la correspondance du visage : %1</translation>
    </message>
    <message>
        <source>Save the Face Mapping Table</source>
        <translation>Enregistrer la table de correspondance du visage</translation>
    </message>
    <message>
        <source>Edit Face Mapping</source>
        <translation>Modifier la correspondance du visage</translation>
    </message>
    <message>
        <source>Recognised from the model&apos;s names</source>
        <translation>Reconnue d&apos;après les noms du modèle</translation>
    </message>
</context>
<context>
    <name>thespis::editor::ClipLibraryPanel</name>
    <message>
        <source>Clip</source>
        <translation>Clip</translation>
    </message>
    <message>
        <source>Source</source>
        <translation>Source</translation>
    </message>
    <message>
        <source>keyframes in the scenario</source>
        <translation>clés dans le scénario</translation>
    </message>
    <message>
        <source>Drag onto a track of %1</source>
        <translation>Faire glisser sur une piste de %1</translation>
    </message>
    <message>
        <source>Drag a clip onto a track of its character to add an action; drop BVH or glTF files here to import them</source>
        <translation>Faites glisser un clip sur une piste de son personnage pour ajouter une action ; déposez ici des fichiers BVH ou glTF pour les importer</translation>
    </message>
    <message>
        <source>idle motion from %1</source>
        <translation>mouvement de repos tiré de %1</translation>
    </message>
    <message>
        <source>Motion synthesis</source>
        <translation>Synthèse de mouvement</translation>
    </message>
    <message>
        <source>Idle</source>
        <translation>Attente</translation>
    </message>
    <message>
        <source>no idle database found</source>
        <translation>aucune base de mouvement d’attente trouvée</translation>
    </message>
    <message>
        <source>standing idle from %1</source>
        <translation>attente debout tirée de %1</translation>
    </message>
    <message>
        <source>Drag onto a body track: the character stands, shifting its weight and moving a little, for as long as the scenario plays</source>
        <translation>Glisser sur une piste de corps : le personnage se tient debout, déplace son poids et bouge un peu, tant que le scénario joue</translation>
    </message>
</context>
<context>
    <name>thespis::editor::ClipSettingsBox</name>
    <message>
        <source>%1: %2</source>
        <translation>%1 : %2</translation>
    </message>
</context>
<context>
    <name>thespis::editor::ContentActions</name>
    <message>
        <source>&amp;Import Motion…</source>
        <translation>&amp;Importer un mouvement…</translation>
    </message>
    <message>
        <source>Add BVH motion capture or glTF animations as clips of a character</source>
        <translation>Ajouter de la capture de mouvement BVH ou des animations glTF comme clips d’un personnage</translation>
    </message>
    <message>
        <source>&amp;Add Character…</source>
        <translation>&amp;Ajouter un personnage…</translation>
    </message>
    <message>
        <source>Add a character on the built-in humanoid or a glTF model</source>
        <translation>Ajouter un personnage sur l’humanoïde intégré ou sur un modèle glTF</translation>
    </message>
    <message>
        <source>&amp;Duplicate Character</source>
        <translation>&amp;Dupliquer le personnage</translation>
    </message>
    <message>
        <source>A copy of the current character, a metre to its right</source>
        <translation>Une copie du personnage courant, un mètre à sa droite</translation>
    </message>
    <message>
        <source>Re&amp;name Character…</source>
        <translation>Re&amp;nommer le personnage…</translation>
    </message>
    <message>
        <source>&amp;Remove Character</source>
        <translation>&amp;Supprimer le personnage</translation>
    </message>
    <message>
        <source>Add &amp;Body Layer</source>
        <translation>Ajouter une couche de &amp;corps</translation>
    </message>
    <message>
        <source>A layer of body actions on top of the current character&apos;s</source>
        <translation>Une couche d’actions du corps par-dessus celles du personnage courant</translation>
    </message>
    <message>
        <source>Add &amp;Face Layer</source>
        <translation>Ajouter une couche de &amp;visage</translation>
    </message>
    <message>
        <source>A layer of facial animation (MPEG-4 FAPs)</source>
        <translation>Une couche d’animation faciale (FAP MPEG-4)</translation>
    </message>
    <message>
        <source>Rena&amp;me Layer…</source>
        <translation>Renommer &amp;la couche…</translation>
    </message>
    <message>
        <source>Move Layer &amp;Up</source>
        <translation>&amp;Monter la couche</translation>
    </message>
    <message>
        <source>Move Layer Do&amp;wn</source>
        <translation>Desc&amp;endre la couche</translation>
    </message>
    <message>
        <source>Remove &amp;Layer</source>
        <translation>Supprimer la c&amp;ouche</translation>
    </message>
    <message>
        <source>&amp;Lighting…</source>
        <translation>É&amp;clairage…</translation>
    </message>
    <message>
        <source>Choose the light probe, turn it and set its intensity</source>
        <translation>Choisir la sonde de lumière, la faire pivoter et régler son intensité</translation>
    </message>
    <message>
        <source>Duplicate Character</source>
        <translation>Dupliquer le personnage</translation>
    </message>
    <message>
        <source>Remove Character</source>
        <translation>Supprimer le personnage</translation>
    </message>
    <message>
        <source>Add Body Layer</source>
        <translation>Ajouter une couche de corps</translation>
    </message>
    <message>
        <source>Add Face Layer</source>
        <translation>Ajouter une couche de visage</translation>
    </message>
    <message>
        <source>Move Layer Up</source>
        <translation>Monter la couche</translation>
    </message>
    <message>
        <source>Move Layer Down</source>
        <translation>Descendre la couche</translation>
    </message>
    <message>
        <source>Remove Layer</source>
        <translation>Supprimer la couche</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1 : %2</translation>
    </message>
    <message>
        <source>Import Motion</source>
        <translation>Importer un mouvement</translation>
    </message>
    <message>
        <source>Motion (*.bvh *.gltf *.glb);;BVH motion capture (*.bvh);;glTF (*.gltf *.glb);;All files (*)</source>
        <translation>Mouvement (*.bvh *.gltf *.glb);;Capture de mouvement BVH (*.bvh);;glTF (*.gltf *.glb);;Tous les fichiers (*)</translation>
    </message>
    <message numerus="yes">
        <source>Import %n Clip(s)</source>
        <translation>
            <numerusform>Importer %n clip</numerusform>
            <numerusform>Importer %n clips</numerusform>
        </translation>
    </message>
    <message>
        <source>Imported %1 into %2.</source>
        <translation>Importé dans %2 : %1.</translation>
    </message>
    <message>
        <source>Actor</source>
        <translation>Acteur</translation>
    </message>
    <message>
        <source>Add Character</source>
        <translation>Ajouter un personnage</translation>
    </message>
    <message>
        <source>Rename Character</source>
        <translation>Renommer le personnage</translation>
    </message>
    <message>
        <source>New name:</source>
        <translation>Nouveau nom :</translation>
    </message>
    <message>
        <source>Rename Layer</source>
        <translation>Renommer la couche</translation>
    </message>
    <message>
        <source>Change Lighting</source>
        <translation>Modifier l’éclairage</translation>
    </message>
    <message>
        <source>Add &amp;Gaze at Playhead</source>
        <translation>&amp;Regard à la tête de lecture</translation>
    </message>
    <message>
        <source>The current character looks at the camera (or at the other character) for two seconds from the playhead; pick what it looks at in Properties</source>
        <translation>Le personnage courant regarde la caméra (ou l’autre personnage) pendant deux secondes à partir de la tête de lecture ; choisissez ce qu’il regarde dans Propriétés</translation>
    </message>
    <message>
        <source>Add Gaze</source>
        <translation>Ajouter un regard</translation>
    </message>
</context>
<context>
    <name>thespis::editor::ConversationPanel</name>
    <message>
        <source>The character the visitor talks to</source>
        <translation>Le personnage auquel le visiteur parle</translation>
    </message>
    <message>
        <source>Converse</source>
        <translation>Converser</translation>
    </message>
    <message>
        <source>Hand the character to the conversation from the playhead: it looks at the visitor and answers. Hand Back gives it to the scenario again; nothing it plays stops.</source>
        <translation>Confier le personnage à la conversation à partir de la tête de lecture : il regarde le visiteur et répond. « Rendre » le rend au scénario ; rien de ce qu&apos;il joue ne s&apos;arrête.</translation>
    </message>
    <message>
        <source>Speak answers</source>
        <translation>Dire les réponses</translation>
    </message>
    <message>
        <source>Answers are spoken with face, gestures and gaze; off, they are only written in the transcript. Chosen before Converse.</source>
        <translation>Les réponses sont dites avec le visage, les gestes et le regard ; sinon elles ne sont écrites que dans la transcription. À choisir avant « Converser ».</translation>
    </message>
    <message>
        <source>No bot loaded.</source>
        <translation>Aucun bot chargé.</translation>
    </message>
    <message>
        <source>Load Bot Folder…</source>
        <translation>Charger un dossier de bot…</translation>
    </message>
    <message>
        <source>A folder of AIML, sets, maps, substitutions and properties (Rosie’s lib/ layout or flat)</source>
        <translation>Un dossier d’AIML, d’ensembles, de tables, de substitutions et de propriétés (disposition lib/ de Rosie ou à plat)</translation>
    </message>
    <message>
        <source>Load AIML Files…</source>
        <translation>Charger des fichiers AIML…</translation>
    </message>
    <message>
        <source>One or more .aiml files (and .set, .map, … files, told by their extension)</source>
        <translation>Un ou plusieurs fichiers .aiml (et .set, .map, …, reconnus à leur extension)</translation>
    </message>
    <message>
        <source>What the bot’s files had wrong, by file:line:column; the rest loaded</source>
        <translation>Ce qui n’allait pas dans les fichiers du bot, par fichier:ligne:colonne ; le reste est chargé</translation>
    </message>
    <message>
        <source>The JSGF grammar the recogniser listens with — what the bot can answer — shows here once a bot is loaded.</source>
        <translation>La grammaire JSGF avec laquelle la reconnaissance écoute – ce à quoi le bot sait répondre – s’affiche ici une fois un bot chargé.</translation>
    </message>
    <message>
        <source>Transcript</source>
        <translation>Transcription</translation>
    </message>
    <message>
        <source>Listening Grammar</source>
        <translation>Grammaire d&apos;écoute</translation>
    </message>
    <message>
        <source>What the visitor says (Return sends)</source>
        <translation>Ce que dit le visiteur (Entrée envoie)</translation>
    </message>
    <message>
        <source>Send</source>
        <translation>Envoyer</translation>
    </message>
    <message>
        <source>Hold to Talk</source>
        <translation>Maintenir pour parler</translation>
    </message>
    <message>
        <source>Hold while the visitor speaks into the microphone (or hold Space on the button); let go to hear it</source>
        <translation>Maintenir pendant que le visiteur parle dans le microphone (ou maintenir Espace sur le bouton) ; relâcher pour l’entendre</translation>
    </message>
    <message>
        <source>Hear a Recording…</source>
        <translation>Écouter un enregistrement…</translation>
    </message>
    <message>
        <source>What the visitor says, from a sound file (WAV, FLAC, OGG), recognised as the microphone would be</source>
        <translation>Ce que dit le visiteur, depuis un fichier son (WAV, FLAC, OGG), reconnu comme le serait le microphone</translation>
    </message>
    <message>
        <source>Save State…</source>
        <translation>Enregistrer l&apos;état…</translation>
    </message>
    <message>
        <source>Keep what the visitor told the bot (its predicates, the history) in a JSON file</source>
        <translation>Garder ce que le visiteur a dit au bot (ses prédicats, l’historique) dans un fichier JSON</translation>
    </message>
    <message>
        <source>Load State…</source>
        <translation>Charger l&apos;état…</translation>
    </message>
    <message>
        <source>Converse from a saved state: the bot remembers what it was told</source>
        <translation>Converser depuis un état enregistré : le bot se souvient de ce qu’on lui a dit</translation>
    </message>
    <message>
        <source>No bot loaded yet</source>
        <translation>Aucun bot chargé pour l’instant</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Annuler</translation>
    </message>
    <message>
        <source>Load Bot Folder</source>
        <translation>Charger un dossier de bot</translation>
    </message>
    <message>
        <source>Load AIML Files</source>
        <translation>Charger des fichiers AIML</translation>
    </message>
    <message>
        <source>AIML files (*.aiml);;Bot files (*.aiml *.set *.map *.substitution *.properties *.pdefaults);;All files (*)</source>
        <translation>Fichiers AIML (*.aiml);;Fichiers de bot (*.aiml *.set *.map *.substitution *.properties *.pdefaults);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <source>Hear a Recording</source>
        <translation>Écouter un enregistrement</translation>
    </message>
    <message>
        <source>Sound files (*.wav *.flac *.ogg)</source>
        <translation>Fichiers son (*.wav *.flac *.ogg)</translation>
    </message>
    <message>
        <source>Save Conversation State</source>
        <translation>Enregistrer l&apos;état de la conversation</translation>
    </message>
    <message>
        <source>Conversation state (*.json)</source>
        <translation>État de conversation (*.json)</translation>
    </message>
    <message>
        <source>Load Conversation State</source>
        <translation>Charger l&apos;état de la conversation</translation>
    </message>
    <message>
        <source>%1 left the conversation: the scenario was closed.</source>
        <translation>%1 a quitté la conversation : le scénario a été fermé.</translation>
    </message>
    <message>
        <source>Load “%1”</source>
        <translation>Charger « %1 »</translation>
    </message>
    <message>
        <source>Load the bot shipped with the demo: %1</source>
        <translation>Charger le bot livré avec la démo : %1</translation>
    </message>
    <message>
        <source>%1 converses on, in the rebuilt scenario.</source>
        <translation>%1 poursuit la conversation dans le scénario reconstruit.</translation>
    </message>
    <message>
        <source>%1 left the conversation: the character is gone.</source>
        <translation>%1 a quitté la conversation : le personnage n&apos;existe plus.</translation>
    </message>
    <message>
        <source>The bot is still being prepared: wait, or cancel it first.</source>
        <translation>Le bot est encore en préparation : attendez, ou annulez d&apos;abord.</translation>
    </message>
    <message numerus="yes">
        <source>%1 and %n more</source>
        <translation>
            <numerusform>%1 et %n autre</numerusform>
            <numerusform>%1 et %n autres</numerusform>
        </translation>
    </message>
    <message>
        <source>Not listening</source>
        <translation>N&apos;écoute pas</translation>
    </message>
    <message>
        <source>Cancelled: the recogniser was not opened. Type what the visitor says.</source>
        <translation>Annulé : la reconnaissance n&apos;a pas été ouverte. Tapez ce que dit le visiteur.</translation>
    </message>
    <message numerus="yes">
        <source>%n word(s) not in the dictionary, pronounced by espeak-ng.</source>
        <translation>
            <numerusform>%n mot absent du dictionnaire, prononcé par espeak-ng.</numerusform>
            <numerusform>%n mots absents du dictionnaire, prononcés par espeak-ng.</numerusform>
        </translation>
    </message>
    <message>
        <source>Pronounced by espeak-ng:</source>
        <translation>Prononcés par espeak-ng :</translation>
    </message>
    <message>
        <source>The recogniser listens for what the bot can answer (opened in %1 s).</source>
        <translation>La reconnaissance écoute ce à quoi le bot sait répondre (ouverte en %1 s).</translation>
    </message>
    <message>
        <source>Cancelled</source>
        <translation>Annulé</translation>
    </message>
    <message>
        <source>Cancelled: the bot was not changed.</source>
        <translation>Annulé : le bot n&apos;a pas changé.</translation>
    </message>
    <message numerus="yes">
        <source>“%1”: %n categories</source>
        <translation>
            <numerusform>« %1 » : %n catégorie</numerusform>
            <numerusform>« %1 » : %n catégories</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>, %n set(s)</source>
        <translation>
            <numerusform>, %n ensemble</numerusform>
            <numerusform>, %n ensembles</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>, %n map(s)</source>
        <translation>
            <numerusform>, %n table</numerusform>
            <numerusform>, %n tables</numerusform>
        </translation>
    </message>
    <message>
        <source>Loaded in %1 s</source>
        <translation>Chargé en %1 s</translation>
    </message>
    <message numerus="yes">
        <source>%n pattern(s) to listen for</source>
        <translation>
            <numerusform>%n motif à écouter</numerusform>
            <numerusform>%n motifs à écouter</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source> (%n left out)</source>
        <translation>
            <numerusform> (%n laissé de côté)</numerusform>
            <numerusform> (%n laissés de côté)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>, %n word(s); wildcards stand for %1 of them.</source>
        <translation>
            <numerusform>, %n mot ; les jokers en remplacent %1.</numerusform>
            <numerusform>, %n mots ; les jokers en remplacent %1.</numerusform>
        </translation>
    </message>
    <message>
        <source>Nothing to listen for: %1 Type what the visitor says.</source>
        <translation>Rien à écouter : %1 Tapez ce que dit le visiteur.</translation>
    </message>
    <message numerus="yes">
        <source>Loaded %n categories in %1 s.</source>
        <translation>
            <numerusform>%n catégorie chargée en %1 s.</numerusform>
            <numerusform>%n catégories chargées en %1 s.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n problem(s) in its files: the rest loaded.</source>
        <translation>
            <numerusform>%n problème dans ses fichiers : le reste est chargé.</numerusform>
            <numerusform>%n problèmes dans ses fichiers : le reste est chargé.</numerusform>
        </translation>
    </message>
    <message>
        <source>Bot loaded</source>
        <translation>Bot chargé</translation>
    </message>
    <message numerus="yes">
        <source>Bot “%1” loaded: %n categories.</source>
        <translation>
            <numerusform>Bot « %1 » chargé : %n catégorie.</numerusform>
            <numerusform>Bot « %1 » chargé : %n catégories.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 converses with the new bot.</source>
        <translation>%1 converse avec le nouveau bot.</translation>
    </message>
    <message>
        <source>Load a bot first: it is what the character answers with.</source>
        <translation>Chargez d&apos;abord un bot : c&apos;est avec lui que le personnage répond.</translation>
    </message>
    <message>
        <source>Open a scenario and choose the character who converses.</source>
        <translation>Ouvrez un scénario et choisissez le personnage qui converse.</translation>
    </message>
    <message>
        <source>%1 converses with the visitor (%2).</source>
        <translation>%1 converse avec le visiteur (%2).</translation>
    </message>
    <message>
        <source>%1 is handed back to the scenario.</source>
        <translation>%1 est rendu(e) au scénario.</translation>
    </message>
    <message>
        <source>Answering…</source>
        <translation>Répond…</translation>
    </message>
    <message>
        <source>Cancelled: the character was told nothing.</source>
        <translation>Annulé : on n&apos;a rien dit au personnage.</translation>
    </message>
    <message>
        <source>Heard: “%1” — confidence %2</source>
        <translation>Entendu : « %1 » – confiance %2</translation>
    </message>
    <message>
        <source>Not understood — confidence %1; nothing of the grammar fits.</source>
        <translation>Pas compris – confiance %1 ; rien de la grammaire ne convient.</translation>
    </message>
    <message>
        <source>Not understood — confidence %1; nearest: “%2”.</source>
        <translation>Pas compris – confiance %1 ; le plus proche : « %2 ».</translation>
    </message>
    <message>
        <source>heard, confidence %1</source>
        <translation>entendu, confiance %1</translation>
    </message>
    <message>
        <source>Typed: “%1”</source>
        <translation>Tapé : « %1 »</translation>
    </message>
    <message>
        <source>typed</source>
        <translation>tapé</translation>
    </message>
    <message>
        <source>Nothing was heard: hold the button while the visitor speaks.</source>
        <translation>Rien entendu : maintenez le bouton pendant que le visiteur parle.</translation>
    </message>
    <message>
        <source>Nothing to save: no character converses.</source>
        <translation>Rien à enregistrer : aucun personnage ne converse.</translation>
    </message>
    <message>
        <source>Saved</source>
        <translation>Enregistré</translation>
    </message>
    <message>
        <source>What the visitor told the bot is in “%1”.</source>
        <translation>Ce que le visiteur a dit au bot est dans « %1 ».</translation>
    </message>
    <message>
        <source>%1 converses on from “%2”.</source>
        <translation>%1 reprend la conversation depuis « %2 ».</translation>
    </message>
    <message>
        <source>Loaded</source>
        <translation>Chargé</translation>
    </message>
    <message>
        <source>The conversation goes on from “%1”.</source>
        <translation>La conversation reprend depuis « %1 ».</translation>
    </message>
    <message>
        <source>Hand Back</source>
        <translation>Rendre</translation>
    </message>
    <message>
        <source>Listening… %1 s — let go when the visitor is done.</source>
        <translation>À l’écoute… %1 s – relâchez quand le visiteur a fini.</translation>
    </message>
    <message>
        <source>No microphone found — type what the visitor says, or use “Hear a Recording…”.</source>
        <translation>Aucun microphone trouvé – tapez ce que dit le visiteur, ou utilisez « Écouter un enregistrement… ».</translation>
    </message>
    <message>
        <source>Microphone: %1. Load a bot to talk to.</source>
        <translation>Microphone : %1. Chargez un bot à qui parler.</translation>
    </message>
    <message>
        <source>Microphone: %1. Hold to Talk works once the recogniser is open.</source>
        <translation>Microphone : %1. « Maintenir pour parler » marche une fois la reconnaissance ouverte.</translation>
    </message>
    <message>
        <source>Microphone: %1. Hold “Hold to Talk” while the visitor speaks.</source>
        <translation>Microphone : %1. Maintenez « Maintenir pour parler » pendant que le visiteur parle.</translation>
    </message>
    <message>
        <source>Ready to listen</source>
        <translation>Prêt à écouter</translation>
    </message>
    <message>
        <source>the script&apos;s bot</source>
        <translation>le bot du script</translation>
    </message>
    <message>
        <source>%1 takes questions: the script handed the conversation over.</source>
        <translation>%1 répond aux questions : le script a passé la main à la conversation.</translation>
    </message>
    <message>
        <source>The recogniser listens with the same language as a graph of %1 states and %2 word arcs.</source>
        <translation>La reconnaissance écoute le même langage sous forme de graphe de %1 états et %2 arcs de mots.</translation>
    </message>
</context>
<context>
    <name>thespis::editor::ConversationTranscript</name>
    <message>
        <source>Who</source>
        <translation>Qui</translation>
    </message>
    <message>
        <source>Said</source>
        <translation>Dit</translation>
    </message>
    <message>
        <source>Spoken (s)</source>
        <translation>Dit à (s)</translation>
    </message>
    <message>
        <source>Visitor</source>
        <translation>Visiteur</translation>
    </message>
    <message>
        <source>(not understood)</source>
        <translation>(pas compris)</translation>
    </message>
    <message>
        <source>learned</source>
        <translation>appris</translation>
    </message>
    <message>
        <source>not spoken</source>
        <translation>non dit</translation>
    </message>
    <message>
        <source>(no answer: no category matched)</source>
        <translation>(pas de réponse : aucune catégorie ne correspond)</translation>
    </message>
    <message>
        <source>Source</source>
        <translation>Source</translation>
    </message>
</context>
<context>
    <name>thespis::editor::CurvePanel</name>
    <message>
        <source>Weight</source>
        <translation>Poids</translation>
    </message>
    <message>
        <source>Scale</source>
        <translation>Échelle</translation>
    </message>
    <message>
        <source>Constant</source>
        <translation>Constante</translation>
    </message>
    <message>
        <source>Linear fade</source>
        <translation>Fondu linéaire</translation>
    </message>
    <message>
        <source>Cubic fade</source>
        <translation>Fondu cubique</translation>
    </message>
    <message>
        <source>Linear ADSR</source>
        <translation>ADSR linéaire</translation>
    </message>
    <message>
        <source>Cubic ADSR</source>
        <translation>ADSR cubique</translation>
    </message>
    <message>
        <source>Keyframed</source>
        <translation>Par clés</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Edit</source>
        <translation>Édition</translation>
    </message>
    <message>
        <source>Shape</source>
        <translation>Forme</translation>
    </message>
    <message>
        <source>Attack / fade in</source>
        <translation>Attaque / entrée</translation>
    </message>
    <message>
        <source>Decay</source>
        <translation>Déclin</translation>
    </message>
    <message>
        <source>Sustain</source>
        <translation>Maintien</translation>
    </message>
    <message>
        <source>Release / fade out</source>
        <translation>Relâchement / sortie</translation>
    </message>
    <message>
        <source>Peak / value</source>
        <translation>Pic / valeur</translation>
    </message>
    <message>
        <source>Key time</source>
        <translation>Temps de la clé</translation>
    </message>
    <message>
        <source>Key value</source>
        <translation>Valeur de la clé</translation>
    </message>
    <message>
        <source>Delete Curve Keys</source>
        <translation>Supprimer les clés de courbe</translation>
    </message>
    <message>
        <source>Change Tangent</source>
        <translation>Modifier la tangente</translation>
    </message>
    <message>
        <source>Set Tangent Mode</source>
        <translation>Définir le mode de tangente</translation>
    </message>
    <message>
        <source>Select an action on the timeline to edit its curves.</source>
        <translation>Sélectionnez une action sur la ligne temporelle pour modifier ses courbes.</translation>
    </message>
    <message>
        <source>No action selected</source>
        <translation>Aucune action sélectionnée</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;%2 · %3</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;%2 · %3</translation>
    </message>
    <message>
        <source>Change Weight Curve</source>
        <translation>Modifier la courbe de poids</translation>
    </message>
    <message>
        <source>Change Scale Curve</source>
        <translation>Modifier la courbe d’échelle</translation>
    </message>
    <message>
        <source>Add Curve Key</source>
        <translation>Ajouter une clé de courbe</translation>
    </message>
    <message numerus="yes">
        <source>Move %n Curve Key(s)</source>
        <translation>
            <numerusform>Déplacer %n clé de courbe</numerusform>
            <numerusform>Déplacer %n clés de courbe</numerusform>
        </translation>
    </message>
    <message>
        <source>Set Curve Key</source>
        <translation>Définir la clé de courbe</translation>
    </message>
    <message>
        <source>Dominance (coarticulation)</source>
        <translation>Dominance (coarticulation)</translation>
    </message>
    <message>
        <source>How sharply the dominance curve peaks (paper eq. 3): over the action, C_α(x) = e^(−α·2|x−0.5|) − 2|x−0.5|·e^(−α), 0 at both ends and the peak in the middle. A small α gives a broad hump, a large α a narrow spike.</source>
        <translation>À quel point la courbe de dominance est pointue (équation 3 de l’article) : sur l’action, C_α(x) = e^(−α·2|x−0.5|) − 2|x−0.5|·e^(−α), 0 aux deux extrémités et le pic au milieu. Un petit α donne une bosse large, un grand α un pic étroit.</translation>
    </message>
    <message>
        <source>Dominance α</source>
        <translation>Dominance α</translation>
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
    <message>
        <source>Not found</source>
        <translation>Introuvable</translation>
    </message>
</context>
<context>
    <name>thespis::editor::ExportMotionDialog</name>
    <message>
        <source>Export Motion</source>
        <translation>Exporter le mouvement</translation>
    </message>
    <message>
        <source>A character&apos;s motion over the whole scenario, as the studio plays it, for Blender, three.js and game engines: a glTF file (.glb) with the character and its motion, or a BVH clip.</source>
        <translation>Le mouvement d&apos;un personnage sur tout le scénario, tel que le studio le joue, pour Blender, three.js et les moteurs de jeu : un fichier glTF (.glb) avec le personnage et son mouvement, ou un clip BVH.</translation>
    </message>
    <message>
        <source>%1 (built-in humanoid)</source>
        <translation>%1 (humanoïde intégré)</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Character:</source>
        <translation>Personnage :</translation>
    </message>
    <message>
        <source> fps</source>
        <translation> i/s</translation>
    </message>
    <message>
        <source>Frame rate:</source>
        <translation>Cadence :</translation>
    </message>
    <message>
        <source>Choose…</source>
        <translation>Choisir…</translation>
    </message>
    <message>
        <source>Write to:</source>
        <translation>Écrire dans :</translation>
    </message>
    <message>
        <source>Animation only (.glb): the joints and the motion without meshes and materials, to play onto a model already in the other tool</source>
        <translation>Animation seule (.glb) : les articulations et le mouvement sans maillages ni matériaux, à jouer sur un modèle déjà dans l&apos;autre outil</translation>
    </message>
    <message>
        <source>Not exported yet</source>
        <translation>Pas encore exporté</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exporter</translation>
    </message>
    <message>
        <source>glTF 2.0 (*.glb);;BVH motion (*.bvh)</source>
        <translation>glTF 2.0 (*.glb);;Mouvement BVH (*.bvh)</translation>
    </message>
    <message>
        <source>“Animation only” goes with a .glb file; a BVH file is always the motion alone.</source>
        <translation>« Animation seule » va avec un fichier .glb ; un fichier BVH est toujours le mouvement seul.</translation>
    </message>
    <message>
        <source>Exported</source>
        <translation>Exporté</translation>
    </message>
    <message numerus="yes">
        <source>Wrote %1: %n frame(s) at %2 fps.</source>
        <translation>
            <numerusform>%1 écrit : %n image à %2 i/s.</numerusform>
            <numerusform>%1 écrit : %n images à %2 i/s.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>thespis::editor::ExportPackageDialog</name>
    <message>
        <source>Export Package</source>
        <translation>Exporter un paquet</translation>
    </message>
    <message>
        <source>One file with the scenario and every file it names, which Thespis opens anywhere (File ▸ Open) and thespis-cli plays or imports.</source>
        <translation>Un seul fichier avec le scénario et tous les fichiers qu’il nomme, que Thespis ouvre partout (Fichier ▸ Ouvrir) et que thespis-cli joue ou importe.</translation>
    </message>
    <message>
        <source>In the package</source>
        <translation>Dans le paquet</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>Taille</translation>
    </message>
    <message>
        <source>Named by</source>
        <translation>Nommé par</translation>
    </message>
    <message>
        <source>Choose…</source>
        <translation>Choisir…</translation>
    </message>
    <message>
        <source>Write to:</source>
        <translation>Écrire dans :</translation>
    </message>
    <message>
        <source>Not exported yet</source>
        <translation>Pas encore exporté</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exporter</translation>
    </message>
    <message>
        <source>Thespis packages (*.thespkg)</source>
        <translation>Paquets Thespis (*.thespkg)</translation>
    </message>
    <message>
        <source>the scenario itself, with its scripts and gestures</source>
        <translation>le scénario lui-même, avec ses scripts et ses gestes</translation>
    </message>
    <message numerus="yes">
        <source>The scenario and %n file(s), %1 before compression.</source>
        <translation>
            <numerusform>Le scénario et %n fichier, %1 avant compression.</numerusform>
            <numerusform>Le scénario et %n fichiers, %1 avant compression.</numerusform>
        </translation>
    </message>
    <message>
        <source>Exported</source>
        <translation>Exporté</translation>
    </message>
    <message>
        <source>Wrote %1: %2 (%3 before compression).</source>
        <translation>%1 écrit : %2 (%3 avant compression).</translation>
    </message>
    <message>
        <source>Bake the lighting first where a character has no bake or an out-of-date one (the new bakes go into the package only)</source>
        <translation>Précalculer d’abord l’éclairage des personnages sans précalcul ou avec un précalcul périmé (les nouveaux précalculs ne vont que dans le paquet)</translation>
    </message>
    <message>
        <source>Baked the lighting of %1.</source>
        <translation>Éclairage de %1 précalculé.</translation>
    </message>
</context>
<context>
    <name>thespis::editor::FaceMappingDialog</name>
    <message>
        <source>Face mapping tables (*.json);;All files (*)</source>
        <translation>Tables de correspondance du visage (*.json);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <source>Face Mapping of %1</source>
        <translation>Correspondance du visage de %1</translation>
    </message>
    <message>
        <source>Each row drives one of the model&apos;s morph targets by a face channel: the target&apos;s weight is the channel&apos;s value times the coefficient (of its positive or negative part only, when one side is chosen).</source>
        <translation>Chaque ligne anime une des cibles de morphing du modèle par un canal du visage : le poids de la cible est la valeur du canal multipliée par le coefficient (de sa seule partie positive ou négative, quand un côté est choisi).</translation>
    </message>
    <message>
        <source>Morph target</source>
        <translation>Cible de morphing</translation>
    </message>
    <message>
        <source>Channel</source>
        <translation>Canal</translation>
    </message>
    <message>
        <source>Coefficient</source>
        <translation>Coefficient</translation>
    </message>
    <message>
        <source>Side</source>
        <translation>Côté</translation>
    </message>
    <message>
        <source>Joint</source>
        <translation>Articulation</translation>
    </message>
    <message>
        <source>Axis (x, y, z)</source>
        <translation>Axe (x, y, z)</translation>
    </message>
    <message>
        <source>Radians per unit</source>
        <translation>Radians par unité</translation>
    </message>
    <message>
        <source>Add Drive</source>
        <translation>Ajouter une commande</translation>
    </message>
    <message>
        <source>Remove Drive</source>
        <translation>Retirer la commande</translation>
    </message>
    <message>
        <source>Add Joint Drive</source>
        <translation>Ajouter une commande d&apos;articulation</translation>
    </message>
    <message>
        <source>Remove Joint Drive</source>
        <translation>Retirer la commande d&apos;articulation</translation>
    </message>
    <message>
        <source>Load…</source>
        <translation>Charger…</translation>
    </message>
    <message>
        <source>Save As…</source>
        <translation>Enregistrer sous…</translation>
    </message>
    <message>
        <source>Recognise from Model</source>
        <translation>Reconnaître d&apos;après le modèle</translation>
    </message>
    <message>
        <source>The table the model&apos;s names give: ARKit blendshapes, Oculus visemes, expression targets, eye and jaw bones</source>
        <translation>La table que donnent les noms du modèle : blendshapes ARKit, visèmes Oculus, cibles d&apos;expression, os des yeux et de la mâchoire</translation>
    </message>
    <message>
        <source>Morph targets:</source>
        <translation>Cibles de morphing :</translation>
    </message>
    <message>
        <source>Joints:</source>
        <translation>Articulations :</translation>
    </message>
    <message>
        <source>Load a Face Mapping Table</source>
        <translation>Charger une table de correspondance du visage</translation>
    </message>
    <message>
        <source>Save the Face Mapping Table</source>
        <translation>Enregistrer la table de correspondance du visage</translation>
    </message>
    <message>
        <source>Both</source>
        <translation>Les deux</translation>
    </message>
    <message>
        <source>Positive values only</source>
        <translation>Valeurs positives seulement</translation>
    </message>
    <message>
        <source>Negative values only</source>
        <translation>Valeurs négatives seulement</translation>
    </message>
    <message>
        <source>%1 has no morph target %2: those rows move nothing.</source>
        <translation>%1 n&apos;a pas de cible de morphing %2 : ces lignes ne déplacent rien.</translation>
    </message>
    <message>
        <source>%1 has no joint %2: those rows turn nothing.</source>
        <translation>%1 n&apos;a pas d&apos;articulation %2 : ces lignes ne tournent rien.</translation>
    </message>
    <message>
        <source>Every morph target and joint the table names is in %1.</source>
        <translation>Chaque cible de morphing et articulation que nomme la table existe dans %1.</translation>
    </message>
    <message>
        <source>Could not load the face mapping table.</source>
        <translation>Impossible de charger la table de correspondance du visage.</translation>
    </message>
    <message>
        <source>Could not save the face mapping table.</source>
        <translation>Impossible d&apos;enregistrer la table de correspondance du visage.</translation>
    </message>
</context>
<context>
    <name>thespis::editor::FacePosePanel</name>
    <message>
        <source>Whose face to pose</source>
        <translation>Le visage à poser</translation>
    </message>
    <message>
        <source>Pose</source>
        <translation>Poser</translation>
    </message>
    <message>
        <source>Show the pose on the character&apos;s face in the 3D view (close up), over what the face plays; the document does not change</source>
        <translation>Montrer la pose sur le visage du personnage dans la vue 3D (en gros plan), par-dessus ce que joue le visage ; le document ne change pas</translation>
    </message>
    <message>
        <source>From Playhead</source>
        <translation>Depuis la tête de lecture</translation>
    </message>
    <message>
        <source>Start from the character&apos;s face as it is at the playhead</source>
        <translation>Partir du visage du personnage tel qu’il est à la tête de lecture</translation>
    </message>
    <message>
        <source>Neutral</source>
        <translation>Neutre</translation>
    </message>
    <message>
        <source>Every slider back to 0: the neutral face</source>
        <translation>Tous les curseurs à 0 : le visage neutre</translation>
    </message>
    <message>
        <source>Expressions</source>
        <translation>Expressions</translation>
    </message>
    <message>
        <source>Mouth and jaw</source>
        <translation>Bouche et mâchoire</translation>
    </message>
    <message>
        <source>Eyes and lids</source>
        <translation>Yeux et paupières</translation>
    </message>
    <message>
        <source>Brows</source>
        <translation>Sourcils</translation>
    </message>
    <message>
        <source>Cheeks</source>
        <translation>Joues</translation>
    </message>
    <message>
        <source>Tongue</source>
        <translation>Langue</translation>
    </message>
    <message>
        <source>Head</source>
        <translation>Tête</translation>
    </message>
    <message>
        <source>Nose and ears</source>
        <translation>Nez et oreilles</translation>
    </message>
    <message>
        <source>Visemes</source>
        <translation>Visèmes</translation>
    </message>
    <message>
        <source>face pose</source>
        <translation>pose du visage</translation>
    </message>
    <message>
        <source>The name of the face clip (and gesture) to save</source>
        <translation>Le nom du clip de visage (et du geste) à enregistrer</translation>
    </message>
    <message>
        <source>Gesture too</source>
        <translation>Aussi en geste</translation>
    </message>
    <message>
        <source>Also add a gesture of that name to the character&apos;s gesticon, for scripts and speech to play</source>
        <translation>Ajouter aussi un geste de ce nom au gesticon du personnage, que scripts et parole peuvent jouer</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Enregistrer</translation>
    </message>
    <message>
        <source>Add the pose to the character as a face clip (one undoable step)</source>
        <translation>Ajouter la pose au personnage comme clip de visage (une étape annulable)</translation>
    </message>
    <message>
        <source>Name:</source>
        <translation>Nom :</translation>
    </message>
    <message>
        <source>FAP %1, in %2 units; positive: %3</source>
        <translation>FAP %1, en unités %2 ; positif : %3</translation>
    </message>
    <message>
        <source>viseme %1</source>
        <translation>visème %1</translation>
    </message>
    <message>
        <source>Weight of MPEG-4 viseme %1, in percent</source>
        <translation>Poids du visème MPEG-4 %1, en pour cent</translation>
    </message>
    <message>
        <source>Intensity of the expression, in percent</source>
        <translation>Intensité de l’expression, en pour cent</translation>
    </message>
    <message>
        <source>Cannot show the pose: %1</source>
        <translation>Impossible de montrer la pose : %1</translation>
    </message>
    <message>
        <source>Give the face clip a name.</source>
        <translation>Donnez un nom au clip de visage.</translation>
    </message>
    <message>
        <source>Open a scenario with a character first.</source>
        <translation>Ouvrez d’abord un scénario avec un personnage.</translation>
    </message>
    <message>
        <source>The face is neutral: move a slider first.</source>
        <translation>Le visage est neutre : déplacez d’abord un curseur.</translation>
    </message>
    <message>
        <source>Save Face Pose as Clip and Gesture</source>
        <translation>Enregistrer la pose du visage comme clip et geste</translation>
    </message>
    <message>
        <source>Save Face Pose</source>
        <translation>Enregistrer la pose du visage</translation>
    </message>
    <message>
        <source>Saved face clip &quot;%1&quot;%2.</source>
        <translation>Clip de visage « %1 »%2 enregistré.</translation>
    </message>
    <message>
        <source> and gesture</source>
        <translation> et geste</translation>
    </message>
</context>
<context>
    <name>thespis::editor::GazeProperties</name>
    <message>
        <source>Looks at</source>
        <translation>Regarde</translation>
    </message>
    <message>
        <source>The eyes alone</source>
        <translation>Les yeux seuls</translation>
    </message>
    <message>
        <source>Eyes and head</source>
        <translation>Les yeux et la tête</translation>
    </message>
    <message>
        <source>Eyes, head and shoulders</source>
        <translation>Les yeux, la tête et les épaules</translation>
    </message>
    <message>
        <source>Eyes, head, shoulders and waist</source>
        <translation>Les yeux, la tête, les épaules et la taille</translation>
    </message>
    <message>
        <source>°</source>
        <translation>°</translation>
    </message>
    <message>
        <source>right</source>
        <translation>à droite</translation>
    </message>
    <message>
        <source>left</source>
        <translation>à gauche</translation>
    </message>
    <message>
        <source>up</source>
        <translation>en haut</translation>
    </message>
    <message>
        <source>down</source>
        <translation>en bas</translation>
    </message>
    <message>
        <source>up and right</source>
        <translation>en haut à droite</translation>
    </message>
    <message>
        <source>up and left</source>
        <translation>en haut à gauche</translation>
    </message>
    <message>
        <source>down and right</source>
        <translation>en bas à droite</translation>
    </message>
    <message>
        <source>down and left</source>
        <translation>en bas à gauche</translation>
    </message>
    <message>
        <source>Target:</source>
        <translation>Cible :</translation>
    </message>
    <message>
        <source>Turns:</source>
        <translation>Tourne :</translation>
    </message>
    <message>
        <source>Away by:</source>
        <translation>À côté de :</translation>
    </message>
    <message>
        <source>Toward:</source>
        <translation>Vers :</translation>
    </message>
</context>
<context>
    <name>thespis::editor::GesticonModel</name>
    <message>
        <source>The dependent-joint filter runs over this gesture: spine and neck follow it</source>
        <translation>Le filtre des articulations dépendantes s’applique à ce geste : la colonne et le cou le suivent</translation>
    </message>
    <message>
        <source>Only the joints of the gesture&apos;s clip move</source>
        <translation>Seules les articulations du clip du geste bougent</translation>
    </message>
    <message>
        <source>The gesture drives every joint its clip has</source>
        <translation>Le geste anime toutes les articulations de son clip</translation>
    </message>
    <message>
        <source>Whole body</source>
        <translation>Tout le corps</translation>
    </message>
    <message>
        <source>The gesture drives the joints of mask &quot;%1&quot;</source>
        <translation>Le geste anime les articulations du masque « %1 »</translation>
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
        <source>Body part</source>
        <translation>Partie du corps</translation>
    </message>
    <message>
        <source>Fade in (s)</source>
        <translation>Fondu d’entrée (s)</translation>
    </message>
    <message>
        <source>Fade out (s)</source>
        <translation>Fondu de sortie (s)</translation>
    </message>
    <message>
        <source>Dependent joints</source>
        <translation>Articulations dépendantes</translation>
    </message>
    <message>
        <source>The name speech scripts use to trigger the gesture</source>
        <translation>Le nom qu’utilisent les scripts de parole pour déclencher le geste</translation>
    </message>
    <message>
        <source>The character&apos;s clip the gesture plays</source>
        <translation>Le clip du personnage que joue le geste</translation>
    </message>
    <message>
        <source>The joint mask that limits the gesture to a body part</source>
        <translation>Le masque d’articulations qui limite le geste à une partie du corps</translation>
    </message>
    <message>
        <source>How long the gesture takes to blend in, in seconds</source>
        <translation>Durée du fondu d’entrée du geste, en secondes</translation>
    </message>
    <message>
        <source>How long the gesture takes to blend out, in seconds</source>
        <translation>Durée du fondu de sortie du geste, en secondes</translation>
    </message>
    <message>
        <source>Dependent-joint filter: joints the gesture does not drive (spine, neck) follow it</source>
        <translation>Filtre des articulations dépendantes : les articulations que le geste n’anime pas (colonne, cou) le suivent</translation>
    </message>
    <message>
        <source>Turn Dependent-Joint Filter On</source>
        <translation>Activer le filtre des articulations dépendantes</translation>
    </message>
    <message>
        <source>Turn Dependent-Joint Filter Off</source>
        <translation>Désactiver le filtre des articulations dépendantes</translation>
    </message>
    <message>
        <source>Rename Gesture</source>
        <translation>Renommer le geste</translation>
    </message>
    <message>
        <source>Change Gesture Clip</source>
        <translation>Modifier le clip du geste</translation>
    </message>
    <message>
        <source>Change Gesture Body Part</source>
        <translation>Modifier la partie du corps du geste</translation>
    </message>
    <message>
        <source>A fade time must be a number of seconds.</source>
        <translation>Une durée de fondu doit être un nombre de secondes.</translation>
    </message>
    <message>
        <source>Change Gesture Fade In</source>
        <translation>Modifier le fondu d’entrée du geste</translation>
    </message>
    <message>
        <source>Change Gesture Fade Out</source>
        <translation>Modifier le fondu de sortie du geste</translation>
    </message>
    <message>
        <source>The filter keeps upper-body PCs 1–%1, fades them out to PC %2 and mutes the rest: a later start keeps the gesture closer to its keys</source>
        <translation>Le filtre garde les CP 1–%1 du haut du corps, les atténue jusqu’à la CP %2 et coupe le reste : un début plus tardif garde le geste plus proche de ses clés</translation>
    </message>
    <message>
        <source>Filter PCs</source>
        <translation>CP du filtre</translation>
    </message>
    <message>
        <source>The filter&apos;s band, e.g. 20–30: PCs kept up to the first, muted above the second (paper: 20–30 of 48)</source>
        <translation>La bande du filtre, p. ex. 20–30 : CP gardées jusqu’à la première, coupées au-delà de la seconde (article : 20–30 sur 48)</translation>
    </message>
    <message>
        <source>Write the filter&apos;s band as two PC numbers, e.g. 30–40.</source>
        <translation>Écrire la bande du filtre comme deux numéros de CP, p. ex. 30–40.</translation>
    </message>
    <message>
        <source>Change Filter Band</source>
        <translation>Changer la bande du filtre</translation>
    </message>
    <message>
        <source>Speech plays it at its own speed and holds its stroke while the words last</source>
        <translation>La parole la joue à sa propre vitesse et tient son temps fort tant que durent les mots</translation>
    </message>
    <message>
        <source>Speech stretches or shrinks it to its words</source>
        <translation>La parole l’étire ou la resserre sur ses mots</translation>
    </message>
    <message>
        <source>No stroke marked: speech fits the gesture as a whole</source>
        <translation>Aucun temps fort marqué : la parole ajuste le geste en entier</translation>
    </message>
    <message>
        <source>The stroke, %1 s into the clip, falls on the first stressed word of its words</source>
        <translation>Le temps fort, à %1 s dans le clip, tombe sur le premier mot accentué de ses mots</translation>
    </message>
    <message>
        <source>none</source>
        <translation>aucun</translation>
    </message>
    <message>
        <source>Holds</source>
        <translation>Tient</translation>
    </message>
    <message>
        <source>Stroke (s)</source>
        <translation>Temps fort (s)</translation>
    </message>
    <message>
        <source>Words longer than the gesture: hold its stroke (checked) or stretch it (unchecked)</source>
        <translation>Mots plus longs que le geste : tenir son temps fort (coché) ou l’étirer (non coché)</translation>
    </message>
    <message>
        <source>Where the gesture&apos;s stroke is in its clip, in seconds: speech puts it on the stressed word</source>
        <translation>Où est le temps fort du geste dans son clip, en secondes : la parole le place sur le mot accentué</translation>
    </message>
    <message>
        <source>Hold Gesture Stroke</source>
        <translation>Tenir le temps fort du geste</translation>
    </message>
    <message>
        <source>Stretch Gesture to Its Words</source>
        <translation>Étirer le geste sur ses mots</translation>
    </message>
    <message>
        <source>A stroke is a number of seconds into the clip (below 0: none).</source>
        <translation>Un temps fort est un nombre de secondes dans le clip (sous 0 : aucun).</translation>
    </message>
    <message>
        <source>Mark Gesture Stroke</source>
        <translation>Marquer le temps fort du geste</translation>
    </message>
</context>
<context>
    <name>thespis::editor::GesticonPanel</name>
    <message>
        <source>The character whose gesture database is shown</source>
        <translation>Le personnage dont la base de gestes est affichée</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Ajouter</translation>
    </message>
    <message>
        <source>Add a gesture playing the character&apos;s first clip</source>
        <translation>Ajouter un geste qui joue le premier clip du personnage</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Supprimer</translation>
    </message>
    <message>
        <source>Remove the selected gestures</source>
        <translation>Supprimer les gestes sélectionnés</translation>
    </message>
    <message>
        <source>Rename</source>
        <translation>Renommer</translation>
    </message>
    <message>
        <source>Rename the selected gesture</source>
        <translation>Renommer le geste sélectionné</translation>
    </message>
    <message>
        <source>Preview</source>
        <translation>Aperçu</translation>
    </message>
    <message>
        <source>The character has no clips to make a gesture from</source>
        <translation>Le personnage n’a aucun clip pour créer un geste</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Arrêter</translation>
    </message>
    <message>
        <source>Stop the preview and show the document again</source>
        <translation>Arrêter l’aperçu et réafficher le document</translation>
    </message>
    <message>
        <source>Character &quot;%1&quot; has no clips to make a gesture from.</source>
        <translation>Le personnage « %1 » n’a aucun clip pour créer un geste.</translation>
    </message>
    <message>
        <source>gesture</source>
        <translation>geste</translation>
    </message>
    <message>
        <source>Add Gesture</source>
        <translation>Ajouter un geste</translation>
    </message>
    <message numerus="yes">
        <source>Remove %n Gesture(s)</source>
        <translation>
            <numerusform>Supprimer %n geste</numerusform>
            <numerusform>Supprimer %n gestes</numerusform>
        </translation>
    </message>
    <message>
        <source>Cannot preview gesture &quot;%1&quot;: %2</source>
        <translation>Impossible de prévisualiser le geste « %1 » : %2</translation>
    </message>
    <message>
        <source>Cannot preview gesture &quot;%1&quot;: its clip has no finite length.</source>
        <translation>Impossible de prévisualiser le geste « %1 » : son clip n’a pas de durée finie.</translation>
    </message>
    <message>
        <source>Before / After</source>
        <translation>Avant / Après</translation>
    </message>
    <message>
        <source>Play the selected gesture twice from the playhead: without the dependent-joint filter, then with it (spine and neck follow the gesture)</source>
        <translation>Jouer le geste sélectionné deux fois depuis la tête de lecture : sans le filtre des articulations dépendantes, puis avec (le dos et le cou suivent le geste)</translation>
    </message>
    <message>
        <source>Before: &quot;%1&quot; without the dependent-joint filter</source>
        <translation>Avant : « %1 » sans le filtre des articulations dépendantes</translation>
    </message>
    <message>
        <source>After: &quot;%1&quot; with the dependent-joint filter (spine and neck follow)</source>
        <translation>Après : « %1 » avec le filtre des articulations dépendantes (le dos et le cou suivent)</translation>
    </message>
    <message>
        <source>Open a scenario to preview its gestures</source>
        <translation>Ouvrez un scénario pour prévisualiser ses gestes</translation>
    </message>
    <message>
        <source>Play the selected gesture on the character from the playhead, over what it plays, as a script would (the document does not change)</source>
        <translation>Joue le geste choisi sur le personnage depuis la tête de lecture, par-dessus ce qu’il joue, comme le ferait un script (le document ne change pas)</translation>
    </message>
    <message>
        <source>Cannot preview gesture &quot;%1&quot;: it cannot be played (Messages says why).</source>
        <translation>Impossible de prévisualiser le geste « %1 » : il ne peut pas être joué (Messages dit pourquoi).</translation>
    </message>
    <message>
        <source>Cannot preview gesture &quot;%1&quot; with the dependent-joint filter: the scenario names no posture bases (a .pca file made by thespis-cli train-pca).</source>
        <translation>Impossible de prévisualiser le geste « %1 » avec le filtre des articulations dépendantes : le scénario ne nomme aucune base de postures (un fichier .pca fait par thespis-cli train-pca).</translation>
    </message>
</context>
<context>
    <name>thespis::editor::IdleProperties</name>
    <message>
        <source>Idle motion</source>
        <translation>Mouvement d’attente</translation>
    </message>
    <message>
        <source>Choose…</source>
        <translation>Choisir…</translation>
    </message>
    <message>
        <source>Play another idle motion database (.idle, made by thespis-cli build-idle)</source>
        <translation>Jouer une autre base de mouvement d’attente (.idle, faite par thespis-cli build-idle)</translation>
    </message>
    <message>
        <source>Which motion program the character follows: characters with different seeds shift their weight at different times</source>
        <translation>Le programme de mouvement que suit le personnage : des personnages de graines différentes déplacent leur poids à des moments différents</translation>
    </message>
    <message>
        <source>Size of the small posture variations: 0 none, 1 as much as in the recordings</source>
        <translation>Taille des petites variations de posture : 0 aucune, 1 autant que dans les enregistrements</translation>
    </message>
    <message>
        <source>Database:</source>
        <translation>Base :</translation>
    </message>
    <message>
        <source>Seed:</source>
        <translation>Graine :</translation>
    </message>
    <message>
        <source>Variations:</source>
        <translation>Variations :</translation>
    </message>
    <message>
        <source>Change Idle Seed</source>
        <translation>Changer la graine de l’attente</translation>
    </message>
    <message>
        <source>Change Idle Variations</source>
        <translation>Changer les variations de l’attente</translation>
    </message>
    <message>
        <source>Choose an Idle Motion Database</source>
        <translation>Choisir une base de mouvement d’attente</translation>
    </message>
    <message>
        <source>Idle motion databases (*.idle)</source>
        <translation>Bases de mouvement d’attente (*.idle)</translation>
    </message>
    <message>
        <source>Idle motion (clip &quot;%1&quot;, shared by its actions)</source>
        <translation>Mouvement d’attente (clip « %1 », partagé par ses actions)</translation>
    </message>
    <message>
        <source>Change Idle Database</source>
        <translation>Changer la base de mouvement d’attente</translation>
    </message>
</context>
<context>
    <name>thespis::editor::ImportMotionDialog</name>
    <message>
        <source>CMU (MotionBuilder names)</source>
        <translation>CMU (noms MotionBuilder)</translation>
    </message>
    <message>
        <source>CMU (3ds Max names)</source>
        <translation>CMU (noms 3ds Max)</translation>
    </message>
    <message>
        <source>your mapping</source>
        <translation>votre correspondance</translation>
    </message>
    <message>
        <source>none recognised</source>
        <translation>aucun reconnu</translation>
    </message>
    <message>
        <source>found from the rig</source>
        <translation>déduits du rig</translation>
    </message>
    <message>
        <source>Import Motion</source>
        <translation>Importer un mouvement</translation>
    </message>
    <message>
        <source>File and clips</source>
        <translation>Fichier et clips</translation>
    </message>
    <message>
        <source>What was found</source>
        <translation>Contenu trouvé</translation>
    </message>
    <message>
        <source>Joint in the file</source>
        <translation>Articulation du fichier</translation>
    </message>
    <message>
        <source>Plays as (H-Anim name)</source>
        <translation>Joue le rôle de (nom H-Anim)</translation>
    </message>
    <message>
        <source>Type the H-Anim joint a file joint should drive (l_hip, vl5, skullbase …); leave it empty, or the file&apos;s own name, to leave the joint out. Then Apply Mapping.</source>
        <translation>Saisissez l’articulation H-Anim que doit animer une articulation du fichier (l_hip, vl5, skullbase …) ; laissez le champ vide, ou le nom propre au fichier, pour écarter l’articulation. Puis «&#xa0;Appliquer la correspondance&#xa0;».</translation>
    </message>
    <message>
        <source>Apply Mapping</source>
        <translation>Appliquer la correspondance</translation>
    </message>
    <message>
        <source>Load Mapping…</source>
        <translation>Charger une correspondance…</translation>
    </message>
    <message>
        <source>Save Mapping…</source>
        <translation>Enregistrer la correspondance…</translation>
    </message>
    <message>
        <source>Import</source>
        <translation>Importer</translation>
    </message>
    <message>
        <source>Import into:</source>
        <translation>Importer dans :</translation>
    </message>
    <message>
        <source>Load Joint Mapping</source>
        <translation>Charger une correspondance d’articulations</translation>
    </message>
    <message>
        <source>Joint mappings (*.map *.txt);;All files (*)</source>
        <translation>Correspondances d’articulations (*.map *.txt);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <source>Save Joint Mapping</source>
        <translation>Enregistrer la correspondance d’articulations</translation>
    </message>
    <message>
        <source>Joint mappings (*.map)</source>
        <translation>Correspondances d’articulations (*.map)</translation>
    </message>
    <message>
        <source>There is no character to import into: add one first (Character ▸ Add Character…).</source>
        <translation>Il n’y a aucun personnage dans lequel importer : ajoutez-en d’abord un (Personnage ▸ Ajouter un personnage…).</translation>
    </message>
    <message>
        <source>cannot be read</source>
        <translation>illisible</translation>
    </message>
    <message>
        <source>moves none of the character&apos;s joints</source>
        <translation>n’anime aucune articulation du personnage</translation>
    </message>
    <message numerus="yes">
        <source>%1, %n frame(s) at %2 fps</source>
        <translation>
            <numerusform>%1, %n image à %2 i/s</numerusform>
            <numerusform>%1, %n images à %2 i/s</numerusform>
        </translation>
    </message>
    <message>
        <source>glTF</source>
        <translation>glTF</translation>
    </message>
    <message>
        <source>BVH</source>
        <translation>BVH</translation>
    </message>
    <message>
        <source>animation</source>
        <translation>animation</translation>
    </message>
    <message>
        <source>No files to import.</source>
        <translation>Aucun fichier à importer.</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1 cannot be read&lt;/b&gt;: %2&lt;br&gt;Nothing of it is imported.</source>
        <translation>&lt;b&gt;%1 est illisible&lt;/b&gt; : %2&lt;br&gt;Rien n’en est importé.</translation>
    </message>
    <message numerus="yes">
        <source>&lt;b&gt;%1&lt;/b&gt;: %2, %n frame(s) at %3 fps.</source>
        <translation>
            <numerusform>&lt;b&gt;%1&lt;/b&gt; : %2, %n image à %3 i/s.</numerusform>
            <numerusform>&lt;b&gt;%1&lt;/b&gt; : %2, %n images à %3 i/s.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Joint names: %1; it moves %n of the character&apos;s joints.</source>
        <translation>
            <numerusform>Noms des articulations : %1 ; le fichier anime %n articulation du personnage.</numerusform>
            <numerusform>Noms des articulations : %1 ; le fichier anime %n articulations du personnage.</numerusform>
        </translation>
    </message>
    <message>
        <source>Unit: %1. The motion is resized to the character by the length of the legs.</source>
        <translation>Unité : %1. Le mouvement est mis à l’échelle du personnage d’après la longueur des jambes.</translation>
    </message>
    <message>
        <source>The body lay %1 in the file: it is stood up (+Y up, facing +Z).</source>
        <translation>Dans le fichier, le corps était orienté autrement (%1) : il est redressé (+Y vers le haut, face à +Z).</translation>
    </message>
    <message>
        <source>Its first frame is a calibration pose (a T-pose): it is left out.</source>
        <translation>La première image est une pose de calibrage (une pose en T) : elle est omise.</translation>
    </message>
    <message numerus="yes">
        <source>%n more</source>
        <translation>
            <numerusform>%n autre</numerusform>
            <numerusform>%n autres</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Joint mapping of %1 (%n joint(s)):</source>
        <translation>
            <numerusform>Correspondance des articulations de %1 (%n articulation) :</numerusform>
            <numerusform>Correspondance des articulations de %1 (%n articulations) :</numerusform>
        </translation>
    </message>
    <message>
        <source>&lt;b&gt;The mapping file cannot be read&lt;/b&gt;: %1</source>
        <translation>&lt;b&gt;Le fichier de correspondance est illisible&lt;/b&gt; : %1</translation>
    </message>
    <message numerus="yes">
        <source>Import %n Clip(s)</source>
        <translation>
            <numerusform>Importer %n clip</numerusform>
            <numerusform>Importer %n clips</numerusform>
        </translation>
    </message>
    <message>
        <source>The character&apos;s joints it leaves at rest: %1.</source>
        <translation>Articulations du personnage laissées au repos : %1.</translation>
    </message>
    <message numerus="yes">
        <source>%n joint(s) have no H-Anim name and keep their own: %1.</source>
        <translation>
            <numerusform>%n articulation n’a pas de nom H-Anim et garde le sien : %1.</numerusform>
            <numerusform>%n articulations n’ont pas de nom H-Anim et gardent le leur : %1.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Of these, %n move(s) nothing of this character (neither they nor a joint below them is in its skeleton): %1.</source>
        <translation>
            <numerusform>Parmi elles, %n ne bouge rien de ce personnage (ni elle ni une articulation en dessous n’est dans son squelette) : %1.</numerusform>
            <numerusform>Parmi elles, %n ne bougent rien de ce personnage (ni elles ni une articulation en dessous ne sont dans son squelette) : %1.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>thespis::editor::JobProgress</name>
    <message>
        <source>Starting…</source>
        <translation>Démarrage…</translation>
    </message>
    <message>
        <source>%1 — %p%</source>
        <translation>%1 — %p%</translation>
    </message>
    <message>
        <source>Cancelled</source>
        <translation>Annulé</translation>
    </message>
    <message>
        <source>Failed</source>
        <translation>Échec</translation>
    </message>
    <message>
        <source>Cancelled: nothing was written.</source>
        <translation>Annulé : rien n’a été écrit.</translation>
    </message>
</context>
<context>
    <name>thespis::editor::JointMaskPanel</name>
    <message>
        <source>The mask to edit; actions that name it all change with it</source>
        <translation>Le masque à modifier ; toutes les actions qui le désignent changent avec lui</translation>
    </message>
    <message>
        <source>Rename…</source>
        <translation>Renommer…</translation>
    </message>
    <message>
        <source>Rename the mask and every action and gesture using it</source>
        <translation>Renommer le masque et mettre à jour les actions et gestes qui l’utilisent</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Supprimer</translation>
    </message>
    <message>
        <source>Delete the mask (only when nothing uses it)</source>
        <translation>Supprimer le masque (seulement s’il n’est pas utilisé)</translation>
    </message>
    <message>
        <source>Presets</source>
        <translation>Préréglages</translation>
    </message>
    <message>
        <source>Replace the weights by a preset</source>
        <translation>Remplacer les poids par un préréglage</translation>
    </message>
    <message>
        <source>Full Body</source>
        <translation>Corps entier</translation>
    </message>
    <message>
        <source>Upper Body</source>
        <translation>Haut du corps</translation>
    </message>
    <message>
        <source>Lower Body</source>
        <translation>Bas du corps</translation>
    </message>
    <message>
        <source>Left Arm</source>
        <translation>Bras gauche</translation>
    </message>
    <message>
        <source>Right Arm</source>
        <translation>Bras droit</translation>
    </message>
    <message>
        <source>Head and Neck</source>
        <translation>Tête et cou</translation>
    </message>
    <message>
        <source>Spine</source>
        <translation>Colonne vertébrale</translation>
    </message>
    <message>
        <source>Apply Mask Preset %1</source>
        <translation>Appliquer le préréglage de masque %1</translation>
    </message>
    <message>
        <source>Mirror</source>
        <translation>Miroir</translation>
    </message>
    <message>
        <source>Swap left and right</source>
        <translation>Permuter gauche et droite</translation>
    </message>
    <message>
        <source>Invert</source>
        <translation>Inverser</translation>
    </message>
    <message>
        <source>Every weight w becomes 1 − w</source>
        <translation>Chaque poids w devient 1 − w</translation>
    </message>
    <message>
        <source>Mirror Mask</source>
        <translation>Masque en miroir</translation>
    </message>
    <message>
        <source>Invert Mask</source>
        <translation>Inverser le masque</translation>
    </message>
    <message>
        <source>Paint Mask</source>
        <translation>Peindre le masque</translation>
    </message>
    <message>
        <source>Set Joint Weight</source>
        <translation>Définir le poids de l’articulation</translation>
    </message>
    <message>
        <source>New Mask</source>
        <translation>Nouveau masque</translation>
    </message>
    <message>
        <source>Name of the new mask:</source>
        <translation>Nom du nouveau masque :</translation>
    </message>
    <message>
        <source>mask</source>
        <translation>masque</translation>
    </message>
    <message>
        <source>Add Mask %1</source>
        <translation>Ajouter le masque %1</translation>
    </message>
    <message>
        <source>Rename Mask</source>
        <translation>Renommer le masque</translation>
    </message>
    <message>
        <source>New name:</source>
        <translation>Nouveau nom :</translation>
    </message>
    <message>
        <source>Delete Mask %1</source>
        <translation>Supprimer le masque %1</translation>
    </message>
    <message>
        <source>New</source>
        <translation>Nouveau</translation>
    </message>
    <message>
        <source>Add a mask of the body&apos;s joints or of the face&apos;s regions</source>
        <translation>Ajouter un masque des articulations du corps ou des régions du visage</translation>
    </message>
    <message>
        <source>Body Mask…</source>
        <translation>Masque du corps…</translation>
    </message>
    <message>
        <source>Face Mask…</source>
        <translation>Masque du visage…</translation>
    </message>
    <message>
        <source>Body</source>
        <translation>Corps</translation>
    </message>
    <message>
        <source>Whole Face</source>
        <translation>Visage entier</translation>
    </message>
    <message>
        <source>Speech (mouth, tongue)</source>
        <translation>Parole (bouche, langue)</translation>
    </message>
    <message>
        <source>Expression (eyes, brows, cheeks)</source>
        <translation>Expression (yeux, sourcils, joues)</translation>
    </message>
    <message>
        <source>Eyes</source>
        <translation>Yeux</translation>
    </message>
    <message>
        <source>Face</source>
        <translation>Visage</translation>
    </message>
    <message>
        <source>Set Face Weight</source>
        <translation>Définir le poids du visage</translation>
    </message>
    <message>
        <source>New Face Mask</source>
        <translation>Nouveau masque du visage</translation>
    </message>
    <message>
        <source>face mask</source>
        <translation>masque du visage</translation>
    </message>
</context>
<context>
    <name>thespis::editor::LightingDialog</name>
    <message>
        <source>Lighting</source>
        <translation>Éclairage</translation>
    </message>
    <message>
        <source>No probe: the default sky</source>
        <translation>Aucune sonde : le ciel par défaut</translation>
    </message>
    <message>
        <source>A light probe (HDR or EXR)</source>
        <translation>Une sonde de lumière (HDR ou EXR)</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>Parcourir…</translation>
    </message>
    <message>
        <source>Latitude–longitude</source>
        <translation>Latitude–longitude</translation>
    </message>
    <message>
        <source>Angular map (mirrored ball, unwrapped)</source>
        <translation>Carte angulaire (sphère miroir, dépliée)</translation>
    </message>
    <message>
        <source>Mirror ball (a photograph)</source>
        <translation>Sphère miroir (une photographie)</translation>
    </message>
    <message>
        <source>Vertical cross</source>
        <translation>Croix verticale</translation>
    </message>
    <message>
        <source>Layout:</source>
        <translation>Disposition :</translation>
    </message>
    <message>
        <source>Turned about the vertical:</source>
        <translation>Rotation autour de la verticale :</translation>
    </message>
    <message>
        <source>Intensity:</source>
        <translation>Intensité :</translation>
    </message>
    <message>
        <source>The probe</source>
        <translation>La sonde</translation>
    </message>
    <message>
        <source>The light the characters receive</source>
        <translation>La lumière que reçoivent les personnages</translation>
    </message>
    <message>
        <source>Set Light</source>
        <translation>Définir l’éclairage</translation>
    </message>
    <message>
        <source>Choose a Light Probe</source>
        <translation>Choisir une sonde de lumière</translation>
    </message>
    <message>
        <source>HDR images (*.hdr *.exr)</source>
        <translation>Images HDR (*.hdr *.exr)</translation>
    </message>
    <message>
        <source>No file chosen.</source>
        <translation>Aucun fichier choisi.</translation>
    </message>
    <message>
        <source>%1 cannot be used as a light probe: %2</source>
        <translation>Impossible d’utiliser %1 comme sonde de lumière : %2</translation>
    </message>
    <message>
        <source>Choose a probe file.</source>
        <translation>Choisissez un fichier de sonde.</translation>
    </message>
    <message>
        <source>The default sky</source>
        <translation>Le ciel par défaut</translation>
    </message>
    <message>
        <source>Reading %1 and projecting its light…</source>
        <translation>Lecture de %1 et projection de sa lumière…</translation>
    </message>
</context>
<context>
    <name>thespis::editor::MessagesPanel</name>
    <message>
        <source>Double-click a message to show what it is about</source>
        <translation>Double-cliquez sur un message pour afficher ce qu’il concerne</translation>
    </message>
    <message>
        <source>Nothing to report.</source>
        <translation>Rien à signaler.</translation>
    </message>
</context>
<context>
    <name>thespis::editor::PointingProperties</name>
    <message>
        <source>Points at</source>
        <translation>Montre du doigt</translation>
    </message>
    <message>
        <source>Aims the gesture&apos;s arm at a target while the action plays (BML&apos;s &lt;pointing&gt;)</source>
        <translation>Pointe le bras du geste vers une cible pendant que l’action joue (&lt;pointing&gt; de BML)</translation>
    </message>
    <message>
        <source>Right hand</source>
        <translation>Main droite</translation>
    </message>
    <message>
        <source>Left hand</source>
        <translation>Main gauche</translation>
    </message>
    <message>
        <source>Both hands</source>
        <translation>Les deux mains</translation>
    </message>
    <message>
        <source>Target:</source>
        <translation>Cible :</translation>
    </message>
    <message>
        <source>With:</source>
        <translation>Avec :</translation>
    </message>
</context>
<context>
    <name>thespis::editor::PostureChartPanel</name>
    <message>
        <source>The character whose posture at the playhead is charted</source>
        <translation>Le personnage dont la posture à la tête de lecture est tracée</translation>
    </message>
    <message>
        <source>Each bar: how far the pose is along one principal component of the upper body&apos;s posture space. The line: how far recorded motion typically goes along it. A hand-keyed pose shows more in the high components; the dependent-joint filter fades and mutes them.</source>
        <translation>Chaque barre : la distance de la pose le long d’une composante principale de l’espace des postures du haut du corps. La ligne : la distance qu’atteint typiquement le mouvement enregistré. Une pose animée à la main en montre davantage dans les hautes composantes ; le filtre des articulations dépendantes les atténue puis les coupe.</translation>
    </message>
    <message>
        <source>No character to chart.</source>
        <translation>Aucun personnage à tracer.</translation>
    </message>
    <message>
        <source>No posture bases: name a .pca file (thespis-cli train-pca) as the scenario&apos;s postureBases.</source>
        <translation>Aucune base de postures : nommer un fichier .pca (thespis-cli train-pca) comme postureBases du scénario.</translation>
    </message>
    <message>
        <source>The posture bases could not be read: %1</source>
        <translation>Les bases de postures n’ont pas pu être lues : %1</translation>
    </message>
    <message>
        <source>The character has no body motion to chart.</source>
        <translation>Le personnage n’a pas de mouvement du corps à tracer.</translation>
    </message>
    <message>
        <source>Cannot chart this character&apos;s posture: %1</source>
        <translation>Impossible de tracer la posture de ce personnage : %1</translation>
    </message>
    <message>
        <source>this pose |PC|</source>
        <translation>cette pose |CP|</translation>
    </message>
    <message>
        <source>captured motion, typical (√eigenvalue)</source>
        <translation>mouvement capturé, typique (√valeur propre)</translation>
    </message>
    <message>
        <source>filter fades</source>
        <translation>le filtre atténue</translation>
    </message>
    <message>
        <source>filter mutes</source>
        <translation>le filtre coupe</translation>
    </message>
    <message>
        <source>%1 at %2 s — energy above PC %3: this pose %4 %, captured motion %5 %</source>
        <translation>%1 à %2 s — énergie au-delà de la CP %3 : cette pose %4 %, mouvement capturé %5 %</translation>
    </message>
    <message>
        <source>Nothing plays.</source>
        <translation>Rien ne joue.</translation>
    </message>
</context>
<context>
    <name>thespis::editor::PropertiesPanel</name>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>time stretch ×%1</source>
        <translation>étirement temporel ×%1</translation>
    </message>
    <message>
        <source>time warp over %1</source>
        <translation>distorsion temporelle sur %1</translation>
    </message>
    <message>
        <source>loop forever</source>
        <translation>boucle sans fin</translation>
    </message>
    <message>
        <source>loop ×%1</source>
        <translation>boucle ×%1</translation>
    </message>
    <message>
        <source>mirror left/right</source>
        <translation>miroir gauche/droite</translation>
    </message>
    <message>
        <source>moved to (%1, %2, %3) m</source>
        <translation>déplacé en (%1, %2, %3) m</translation>
    </message>
    <message>
        <source>offset %1</source>
        <translation>décalage de %1</translation>
    </message>
    <message>
        <source>trim %1 – %2</source>
        <translation>coupé à %1 – %2</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Normalized (weighted average)</source>
        <translation>Normalisé (moyenne pondérée)</translation>
    </message>
    <message>
        <source>Additive (on top of the layers below)</source>
        <translation>Additif (par-dessus les couches du dessous)</translation>
    </message>
    <message>
        <source>Override (replaces by its weight)</source>
        <translation>Remplacement (remplace selon son poids)</translation>
    </message>
    <message>
        <source>Hold the first and last pose outside the action</source>
        <translation>Maintenir la première et la dernière pose hors de l’action</translation>
    </message>
    <message>
        <source>Action of:</source>
        <translation>Action de :</translation>
    </message>
    <message>
        <source>Name:</source>
        <translation>Nom :</translation>
    </message>
    <message>
        <source>Clip:</source>
        <translation>Clip :</translation>
    </message>
    <message>
        <source>Start:</source>
        <translation>Début :</translation>
    </message>
    <message>
        <source>Length:</source>
        <translation>Durée :</translation>
    </message>
    <message>
        <source>Fades:</source>
        <translation>Fondus :</translation>
    </message>
    <message>
        <source>Blend mode:</source>
        <translation>Mode de mélange :</translation>
    </message>
    <message>
        <source>Body part:</source>
        <translation>Partie du corps :</translation>
    </message>
    <message>
        <source>Modifiers:</source>
        <translation>Modificateurs :</translation>
    </message>
    <message>
        <source>Rename Action</source>
        <translation>Renommer l’action</translation>
    </message>
    <message>
        <source>Change Clip</source>
        <translation>Modifier le clip</translation>
    </message>
    <message>
        <source>Change Blend Mode</source>
        <translation>Modifier le mode de mélange</translation>
    </message>
    <message>
        <source>Change Body Part</source>
        <translation>Modifier la partie du corps</translation>
    </message>
    <message>
        <source>Change Outside Domain</source>
        <translation>Modifier le comportement hors domaine</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1 : %2</translation>
    </message>
    <message>
        <source>Move Action</source>
        <translation>Déplacer l’action</translation>
    </message>
    <message>
        <source>Move Action: %1</source>
        <translation>Déplacer l’action : %1</translation>
    </message>
    <message>
        <source>No scenario is open.</source>
        <translation>Aucun scénario ouvert.</translation>
    </message>
    <message>
        <source>not saved yet</source>
        <translation>pas encore enregistré</translation>
    </message>
    <message numerus="yes">
        <source>%n character(s)</source>
        <translation>
            <numerusform>%n personnage</numerusform>
            <numerusform>%n personnages</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n action(s)</source>
        <translation>
            <numerusform>%n action</numerusform>
            <numerusform>%n actions</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 ▸ %2%3</source>
        <translation>%1 ▸ %2%3</translation>
    </message>
    <message>
        <source> (locked)</source>
        <translation> (verrouillée)</translation>
    </message>
    <message>
        <source>Whole body</source>
        <translation>Tout le corps</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>inconnu</translation>
    </message>
    <message>
        <source>open-ended (plays until cut off)</source>
        <translation>sans fin (jouée jusqu’à interruption)</translation>
    </message>
    <message>
        <source>none (constant weight %1)</source>
        <translation>aucun (poids constant %1)</translation>
    </message>
    <message numerus="yes">
        <source>keyframed weight curve (%n key(s))</source>
        <translation>
            <numerusform>courbe de poids par clés (%n clé)</numerusform>
            <numerusform>courbe de poids par clés (%n clés)</numerusform>
        </translation>
    </message>
    <message>
        <source>in %1, out %2</source>
        <translation>entrée %1, sortie %2</translation>
    </message>
    <message>
        <source>none</source>
        <translation>aucun</translation>
    </message>
    <message>
        <source>Where it was recorded</source>
        <translation>Là où il a été enregistré</translation>
    </message>
    <message>
        <source>Where the character stands</source>
        <translation>Là où se tient le personnage</translation>
    </message>
    <message>
        <source>Where the previous action leaves it</source>
        <translation>Là où l’action précédente le laisse</translation>
    </message>
    <message>
        <source>Where the motion&apos;s first frame puts the body on the floor (and which way it faces)</source>
        <translation>Où la première image du mouvement place le corps au sol (et dans quelle direction il regarde)</translation>
    </message>
    <message>
        <source>forever</source>
        <translation>sans fin</translation>
    </message>
    <message>
        <source> ×</source>
        <translation> ×</translation>
    </message>
    <message>
        <source>Each time on from where it ended (walks on)</source>
        <translation>Reprend chaque fois là où il s’est arrêté (continue d’avancer)</translation>
    </message>
    <message>
        <source>Starts:</source>
        <translation>Commence :</translation>
    </message>
    <message>
        <source>Plays:</source>
        <translation>Joue :</translation>
    </message>
    <message>
        <source>Change Where the Action Starts</source>
        <translation>Modifier le point de départ de l’action</translation>
    </message>
    <message>
        <source>Change How Often the Action Plays</source>
        <translation>Modifier le nombre de répétitions de l’action</translation>
    </message>
    <message>
        <source>&lt;i&gt;No characters yet: Character ▸ Add Character… adds one, then File ▸ Import Motion… brings in its motion capture.&lt;/i&gt;</source>
        <translation>&lt;i&gt;Aucun personnage pour l’instant : Personnage ▸ Ajouter un personnage… en ajoute un, puis Fichier ▸ Importer un mouvement… apporte sa capture de mouvement.&lt;/i&gt;</translation>
    </message>
    <message>
        <source>&lt;i&gt;Select an action on the timeline, or a character in the scenario outline, to see and edit its properties.&lt;/i&gt;</source>
        <translation>&lt;i&gt;Sélectionnez une action sur la ligne temporelle, ou un personnage dans le plan du scénario, pour voir et modifier ses propriétés.&lt;/i&gt;</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;File: %2&lt;br&gt;%3, %4, %5 markers&lt;br&gt;Length: %6&lt;br&gt;&lt;br&gt;%7</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;Fichier : %2&lt;br&gt;%3, %4, %5 marqueurs&lt;br&gt;Durée : %6&lt;br&gt;&lt;br&gt;%7</translation>
    </message>
    <message>
        <source>dependent joints follow (PCs kept to %1, muted above %2)</source>
        <translation>les articulations dépendantes suivent (CP gardées jusqu’à %1, muettes au-delà de %2)</translation>
    </message>
    <message>
        <source>Face regions:</source>
        <translation>Régions du visage :</translation>
    </message>
    <message>
        <source>Whole face</source>
        <translation>Visage entier</translation>
    </message>
    <message>
        <source>none (dominance weight curve, α %1)</source>
        <translation>aucun (courbe de poids de dominance, α %1)</translation>
    </message>
    <message>
        <source>Change Gaze</source>
        <translation>Changer le regard</translation>
    </message>
    <message>
        <source>Change Pointing</source>
        <translation>Changer le pointage</translation>
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
    <message>
        <source>dependent joints</source>
        <translation>articulations dépendantes</translation>
    </message>
    <message>
        <source>dominance α %1</source>
        <translation>dominance α %1</translation>
    </message>
    <message>
        <source>gaze layer</source>
        <translation>calque de regard</translation>
    </message>
</context>
<context>
    <name>thespis::editor::ScenePreview</name>
    <message>
        <source>The light probe could not be used (the default light shows instead): %1</source>
        <translation>La sonde de lumière n’a pas pu être utilisée (la lumière par défaut la remplace) : %1</translation>
    </message>
</context>
<context>
    <name>thespis::editor::ScriptPanel</name>
    <message>
        <source>What the script prints, and its errors, show here.</source>
        <translation>Ce que le script affiche, et ses erreurs, apparaissent ici.</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Exécuter</translation>
    </message>
    <message>
        <source>Run the script on the scenario shown, while it plays (Ctrl+Return)</source>
        <translation>Exécuter le script sur le scénario affiché, pendant la lecture (Ctrl+Entrée)</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Arrêter</translation>
    </message>
    <message>
        <source>Stop the script now, even in a wait</source>
        <translation>Arrêter le script tout de suite, même pendant une attente</translation>
    </message>
    <message>
        <source>Clear Output</source>
        <translation>Effacer la sortie</translation>
    </message>
    <message>
        <source>The scenario was rebuilt, so the script was stopped.</source>
        <translation>Le scénario a été reconstruit : le script a donc été arrêté.</translation>
    </message>
    <message>
        <source>Running…</source>
        <translation>En cours…</translation>
    </message>
    <message>
        <source>— Run at %1 s —</source>
        <translation>— Lancé à %1 s —</translation>
    </message>
    <message>
        <source>Stopping…</source>
        <translation>Arrêt…</translation>
    </message>
    <message>
        <source>Finished.</source>
        <translation>Terminé.</translation>
    </message>
    <message>
        <source>Stopped.</source>
        <translation>Arrêté.</translation>
    </message>
    <message>
        <source>Open a scenario to run scripts on it.</source>
        <translation>Ouvrez un scénario pour y exécuter des scripts.</translation>
    </message>
    <message>
        <source>Scratch, or a script kept in the scenario</source>
        <translation>Brouillon, ou un script gardé dans le scénario</translation>
    </message>
    <message>
        <source>Scratch</source>
        <translation>Brouillon</translation>
    </message>
    <message>
        <source>Save to Scenario…</source>
        <translation>Enregistrer dans le scénario…</translation>
    </message>
    <message>
        <source>Keep this script in the scenario (saved with it, one undo step)</source>
        <translation>Garder ce script dans le scénario (enregistré avec lui, une étape d’annulation)</translation>
    </message>
    <message>
        <source>Save Script to Scenario</source>
        <translation>Enregistrer le script dans le scénario</translation>
    </message>
    <message>
        <source>Name of the script:</source>
        <translation>Nom du script :</translation>
    </message>
    <message>
        <source>script</source>
        <translation>script</translation>
    </message>
    <message>
        <source>Not run: the scenario&apos;s scripts are not trusted.</source>
        <translation>Non exécuté : les scripts du scénario ne sont pas approuvés.</translation>
    </message>
    <message>
        <source>Save Script “%1”</source>
        <translation>Enregistrer le script « %1 »</translation>
    </message>
</context>
<context>
    <name>thespis::editor::SegmentPanel</name>
    <message>
        <source>The character whose body segments are tagged</source>
        <translation>Le personnage dont les segments du corps sont étiquetés</translation>
    </message>
    <message>
        <source>Filter segments…</source>
        <translation>Filtrer les segments…</translation>
    </message>
    <message>
        <source>Show only the segments whose name or joint contains this text</source>
        <translation>Afficher uniquement les segments dont le nom ou l’articulation contient ce texte</translation>
    </message>
    <message>
        <source>Role:</source>
        <translation>Rôle :</translation>
    </message>
    <message>
        <source>Tag the selected segments as %1. %2</source>
        <translation>Marquer les segments sélectionnés comme %1. %2</translation>
    </message>
    <message>
        <source>Occluder</source>
        <translation>Occulteur</translation>
    </message>
    <message>
        <source>Vertices</source>
        <translation>Sommets</translation>
    </message>
    <message>
        <source>Triangles</source>
        <translation>Triangles</translation>
    </message>
    <message>
        <source>%1 of %2 selected</source>
        <translation>Sélection : %1 sur %2</translation>
    </message>
    <message>
        <source>Click a segment in the viewport to select it (Ctrl toggles, Shift adds). Receivers are left out of the shadow proxy; occluders cast shadows but are not lit.</source>
        <translation>Cliquez sur un segment dans la vue pour le sélectionner (Ctrl bascule, Maj ajoute). Les récepteurs sont exclus du proxy d&apos;ombre ; les occulteurs projettent des ombres mais ne sont pas éclairés.</translation>
    </message>
</context>
<context>
    <name>thespis::editor::SegmentTableModel</name>
    <message>
        <source>No character is shown.</source>
        <translation>Aucun personnage affiché.</translation>
    </message>
    <message numerus="yes">
        <source>Tag %n Segment(s)</source>
        <translation>
            <numerusform>Étiqueter %n segment</numerusform>
            <numerusform>Étiqueter %n segments</numerusform>
        </translation>
    </message>
    <message>
        <source>None</source>
        <translation>Aucun</translation>
    </message>
    <message>
        <source>Receiver</source>
        <translation>Récepteur</translation>
    </message>
    <message>
        <source>Occluder</source>
        <translation>Occulteur</translation>
    </message>
    <message>
        <source>Casts shadows and receives them.</source>
        <translation>Projette des ombres et en reçoit.</translation>
    </message>
    <message>
        <source>Receives shadows but casts none: left out of the shadow proxy (hair, loose clothes).</source>
        <translation>Reçoit des ombres sans en projeter : exclu du proxy d’ombre (cheveux, vêtements amples).</translation>
    </message>
    <message>
        <source>Casts shadows but is not lit itself: no transfer is baked for it (props, phantom geometry).</source>
        <translation>Projette des ombres sans être lui-même éclairé : aucun transfert n’est précalculé pour lui (accessoires, géométrie fantôme).</translation>
    </message>
    <message>
        <source>(root)</source>
        <translation>(racine)</translation>
    </message>
    <message>
        <source>Segment %1 follows joint %2</source>
        <translation>Le segment %1 suit l’articulation %2</translation>
    </message>
    <message>
        <source>Segment</source>
        <translation>Segment</translation>
    </message>
    <message>
        <source>Joint</source>
        <translation>Articulation</translation>
    </message>
    <message>
        <source>Role</source>
        <translation>Rôle</translation>
    </message>
    <message>
        <source>Vertices</source>
        <translation>Sommets</translation>
    </message>
    <message>
        <source>Triangles</source>
        <translation>Triangles</translation>
    </message>
    <message>
        <source>The mesh segment (paper §6.1.3)</source>
        <translation>Le segment du maillage (article, §6.1.3)</translation>
    </message>
    <message>
        <source>The H-Anim joint whose frame the segment follows</source>
        <translation>L’articulation H-Anim dont le segment suit le repère</translation>
    </message>
    <message>
        <source>Receiver: in shadow but casts none. Occluder: casts shadows, not lit. None: both.</source>
        <translation>Récepteur : reçoit les ombres sans en projeter. Occulteur : projette des ombres, non éclairé. Aucun : les deux.</translation>
    </message>
    <message>
        <source>Vertices of the segment</source>
        <translation>Sommets du segment</translation>
    </message>
    <message>
        <source>Triangles of the segment</source>
        <translation>Triangles du segment</translation>
    </message>
</context>
<context>
    <name>thespis::editor::SkeletonView</name>
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
        <source>This scenario has no characters yet.</source>
        <translation>Ce scénario n’a pas encore de personnages.</translation>
    </message>
    <message>
        <source>No scenario is open.
Use File ▸ Open… (Ctrl+O) to open a .thespis file.</source>
        <translation>Aucun scénario ouvert.
Utilisez Fichier ▸ Ouvrir… (Ctrl+O) pour ouvrir un fichier .thespis.</translation>
    </message>
</context>
<context>
    <name>thespis::editor::SpeechPanel</name>
    <message>
        <source>The character who speaks</source>
        <translation>Le personnage qui parle</translation>
    </message>
    <message>
        <source>The espeak-ng voices installed</source>
        <translation>Les voix espeak-ng installées</translation>
    </message>
    <message>
        <source> words/min</source>
        <translation> mots/min</translation>
    </message>
    <message>
        <source>Voice:</source>
        <translation>Voix :</translation>
    </message>
    <message>
        <source>Rate:</source>
        <translation>Débit :</translation>
    </message>
    <message>
        <source>Pitch:</source>
        <translation>Hauteur :</translation>
    </message>
    <message>
        <source>Visemes and their coarticulation</source>
        <translation>Visèmes et leur coarticulation</translation>
    </message>
    <message>
        <source>Preview</source>
        <translation>Aperçu</translation>
    </message>
    <message>
        <source>Say it from the playhead, face and voice, without changing the scenario</source>
        <translation>Le dire depuis la tête de lecture, visage et voix, sans modifier le scénario</translation>
    </message>
    <message>
        <source>Insert at Playhead</source>
        <translation>Insérer à la tête de lecture</translation>
    </message>
    <message>
        <source>Lip Sync a Recording…</source>
        <translation>Synchroniser les lèvres sur un enregistrement…</translation>
    </message>
    <message>
        <source>Align a WAV with the text above as its transcript (empty: the words are recognised) and insert it</source>
        <translation>Aligner un fichier WAV sur le texte ci-dessus comme transcription (vide : les mots sont reconnus) et l’insérer</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Annuler</translation>
    </message>
    <message>
        <source>Close-up</source>
        <translation>Gros plan</translation>
    </message>
    <message>
        <source>Turn the 3D view to the speaker&apos;s face when previewing</source>
        <translation>Tourner la vue 3D vers le visage du personnage qui parle pendant l’aperçu</translation>
    </message>
    <message>
        <source>Nothing spoken yet</source>
        <translation>Rien n’a encore été dit</translation>
    </message>
    <message>
        <source>Lip Sync a Recording</source>
        <translation>Synchroniser les lèvres sur un enregistrement</translation>
    </message>
    <message>
        <source>Sound files (*.wav *.flac *.ogg)</source>
        <translation>Fichiers audio (*.wav *.flac *.ogg)</translation>
    </message>
    <message numerus="yes">
        <source>Previewing %1 s of speech from %2 s: %n viseme(s)</source>
        <translation>
            <numerusform>Aperçu de %1 s de parole depuis %2 s : %n visème</numerusform>
            <numerusform>Aperçu de %1 s de parole depuis %2 s : %n visèmes</numerusform>
        </translation>
    </message>
    <message>
        <source>; not in the gesticon: %1</source>
        <translation> ; absent du gesticon : %1</translation>
    </message>
    <message>
        <source>Previewing</source>
        <translation>Aperçu en cours</translation>
    </message>
    <message>
        <source>Insert Speech</source>
        <translation>Insérer la parole</translation>
    </message>
    <message>
        <source>Inserted</source>
        <translation>Inséré</translation>
    </message>
    <message numerus="yes">
        <source>Inserted at %1 s: %n viseme(s), %2 face and %3 body gesture(s).</source>
        <translation>
            <numerusform>Inséré à %1 s : %n visème, %2 geste(s) du visage et %3 du corps.</numerusform>
            <numerusform>Inséré à %1 s : %n visèmes, %2 geste(s) du visage et %3 du corps.</numerusform>
        </translation>
    </message>
    <message>
        <source>Lip Sync Recording</source>
        <translation>Insérer un enregistrement synchronisé sur les lèvres</translation>
    </message>
    <message numerus="yes">
        <source>Lip-synced “%1”: %n word(s), %2 viseme(s).</source>
        <translation>
            <numerusform>« %1 » synchronisé sur les lèvres : %n mot, %2 visème(s).</numerusform>
            <numerusform>« %1 » synchronisé sur les lèvres : %n mots, %2 visème(s).</numerusform>
        </translation>
    </message>
    <message>
        <source>What the character says. Gestures go around the words they span:
Are you &lt;begin_gesture id=&quot;g1&quot; anim=&quot;raise_eyebrows&quot;/&gt;really sure&lt;end_gesture id=&quot;g1&quot;/&gt;?
Or a BML block:
&lt;bml id=&quot;b1&quot;&gt;&lt;speech id=&quot;s1&quot;&gt;&lt;text&gt;Hello &lt;sync id=&quot;t1&quot;/&gt;there.&lt;/text&gt;&lt;/speech&gt;
&lt;gesture id=&quot;g1&quot; lexeme=&quot;BEAT&quot; stroke=&quot;s1:t1&quot;/&gt;&lt;gaze id=&quot;z1&quot; target=&quot;camera&quot;/&gt;&lt;/bml&gt;</source>
        <translation>Ce que dit le personnage. Les gestes entourent les mots qu’ils couvrent :
Es-tu &lt;begin_gesture id=&quot;g1&quot; anim=&quot;raise_eyebrows&quot;/&gt;vraiment sûr&lt;end_gesture id=&quot;g1&quot;/&gt; ?
Ou un bloc BML :
&lt;bml id=&quot;b1&quot;&gt;&lt;speech id=&quot;s1&quot;&gt;&lt;text&gt;Bonjour &lt;sync id=&quot;t1&quot;/&gt;toi.&lt;/text&gt;&lt;/speech&gt;
&lt;gesture id=&quot;g1&quot; lexeme=&quot;BEAT&quot; stroke=&quot;s1:t1&quot;/&gt;&lt;gaze id=&quot;z1&quot; target=&quot;camera&quot;/&gt;&lt;/bml&gt;</translation>
    </message>
    <message>
        <source>Put the line, its visemes and its gestures (or the BML block&apos;s speech, gestures, head, face and gaze) on the timeline at the playhead (one undo step)</source>
        <translation>Placer la réplique, ses visèmes et ses gestes (ou la parole, les gestes, la tête, le visage et le regard du bloc BML) sur la timeline à la tête de lecture (une seule annulation)</translation>
    </message>
    <message numerus="yes">
        <source>Previewing BML block “%1” from %2 s to %3 s: %n behaviour(s)</source>
        <translation>
            <numerusform>Aperçu du bloc BML « %1 » de %2 s à %3 s : %n comportement</numerusform>
            <numerusform>Aperçu du bloc BML « %1 » de %2 s à %3 s : %n comportements</numerusform>
        </translation>
    </message>
    <message>
        <source>Insert BML</source>
        <translation>Insérer du BML</translation>
    </message>
    <message numerus="yes">
        <source>Inserted BML from %1 s to %2 s: %n speech(es), %3 gesture(s), %4 head gesture(s), %5 face lexeme(s), %6 gaze(s).</source>
        <translation>
            <numerusform>BML inséré de %1 s à %2 s : %n réplique, %3 geste(s), %4 geste(s) de tête, %5 lexème(s) facial(aux), %6 regard(s).</numerusform>
            <numerusform>BML inséré de %1 s à %2 s : %n répliques, %3 geste(s), %4 geste(s) de tête, %5 lexème(s) facial(aux), %6 regard(s).</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>thespis::editor::TargetChoice</name>
    <message>
        <source>The camera, a character (its eyes), a joint of one (&quot;Creon:r_radiocarpal&quot;) or a point in metres (&quot;0.5 1.6 2&quot;)</source>
        <translation>La caméra, un personnage (ses yeux), une articulation d’un personnage (« Creon:r_radiocarpal ») ou un point en mètres (« 0.5 1.6 2 »)</translation>
    </message>
    <message>
        <source>The camera (the viewer)</source>
        <translation>La caméra (le spectateur)</translation>
    </message>
    <message>
        <source>%1&apos;s eyes</source>
        <translation>Les yeux de %1</translation>
    </message>
    <message>
        <source>%1&apos;s right hand</source>
        <translation>La main droite de %1</translation>
    </message>
    <message>
        <source>%1&apos;s left hand</source>
        <translation>La main gauche de %1</translation>
    </message>
</context>
<context>
    <name>thespis::editor::TimelinePanel</name>
    <message>
        <source>&amp;Delete</source>
        <translation>&amp;Supprimer</translation>
    </message>
    <message>
        <source>Ripple De&amp;lete</source>
        <translation>Supprimer et &amp;raccorder</translation>
    </message>
    <message>
        <source>&amp;Copy</source>
        <translation>&amp;Copier</translation>
    </message>
    <message>
        <source>&amp;Paste</source>
        <translation>C&amp;oller</translation>
    </message>
    <message>
        <source>D&amp;uplicate</source>
        <translation>&amp;Dupliquer</translation>
    </message>
    <message>
        <source>&amp;Split at Playhead</source>
        <translation>Sc&amp;inder à la tête de lecture</translation>
    </message>
    <message>
        <source>S&amp;napping</source>
        <translation>&amp;Aimantation</translation>
    </message>
    <message>
        <source>Snap to frames, clip edges, markers and the playhead (hold Ctrl while dragging to bypass)</source>
        <translation>Aimanter aux images, aux bords des clips, aux marqueurs et à la tête de lecture (maintenir Ctrl en faisant glisser pour l’ignorer)</translation>
    </message>
    <message numerus="yes">
        <source>Move %n Action(s)</source>
        <translation>
            <numerusform>Déplacer %n action</numerusform>
            <numerusform>Déplacer %n actions</numerusform>
        </translation>
    </message>
    <message>
        <source>Trim Action</source>
        <translation>Couper l’action</translation>
    </message>
    <message>
        <source>Change Fade In</source>
        <translation>Modifier le fondu d’entrée</translation>
    </message>
    <message>
        <source>Change Fade Out</source>
        <translation>Modifier le fondu de sortie</translation>
    </message>
    <message>
        <source>Mute Layer</source>
        <translation>Désactiver la couche</translation>
    </message>
    <message>
        <source>Unmute Layer</source>
        <translation>Réactiver la couche</translation>
    </message>
    <message>
        <source>Solo Layer</source>
        <translation>Mettre la couche en solo</translation>
    </message>
    <message>
        <source>Unsolo Layer</source>
        <translation>Retirer la couche du solo</translation>
    </message>
    <message>
        <source>Lock Layer</source>
        <translation>Verrouiller la couche</translation>
    </message>
    <message>
        <source>Unlock Layer</source>
        <translation>Déverrouiller la couche</translation>
    </message>
    <message>
        <source>Marker %1</source>
        <translation>Marqueur %1</translation>
    </message>
    <message>
        <source>Add Marker</source>
        <translation>Ajouter un marqueur</translation>
    </message>
    <message>
        <source>Move Marker</source>
        <translation>Déplacer le marqueur</translation>
    </message>
    <message>
        <source>Remove Marker</source>
        <translation>Supprimer le marqueur</translation>
    </message>
    <message>
        <source>Add Action %1</source>
        <translation>Ajouter l’action %1</translation>
    </message>
    <message numerus="yes">
        <source>Ripple Delete %n Action(s)</source>
        <translation>
            <numerusform>Supprimer et raccorder %n action</numerusform>
            <numerusform>Supprimer et raccorder %n actions</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Delete %n Action(s)</source>
        <translation>
            <numerusform>Supprimer %n action</numerusform>
            <numerusform>Supprimer %n actions</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Paste %n Action(s)</source>
        <translation>
            <numerusform>Coller %n action</numerusform>
            <numerusform>Coller %n actions</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Duplicate %n Action(s)</source>
        <translation>
            <numerusform>Dupliquer %n action</numerusform>
            <numerusform>Dupliquer %n actions</numerusform>
        </translation>
    </message>
    <message>
        <source>Select one action to split at the playhead.</source>
        <translation>Sélectionnez une seule action à scinder à la tête de lecture.</translation>
    </message>
    <message>
        <source>Split Action</source>
        <translation>Scinder l’action</translation>
    </message>
    <message>
        <source>Add Idle Motion</source>
        <translation>Ajouter un mouvement d’attente</translation>
    </message>
</context>
<context>
    <name>thespis::editor::VisemeTable</name>
    <message>
        <source>Viseme</source>
        <translation>Visème</translation>
    </message>
    <message>
        <source>Phonemes</source>
        <translation>Phonèmes</translation>
    </message>
    <message>
        <source>α</source>
        <translation>α</translation>
    </message>
    <message>
        <source>Weight</source>
        <translation>Poids</translation>
    </message>
    <message>
        <source>Spread</source>
        <translation>Étendue</translation>
    </message>
    <message>
        <source>Dominance α (paper eq. 3): larger keeps the mouth shape to its own phoneme</source>
        <translation>Dominance α (équation 3 de l’article) : plus elle est grande, plus la forme de la bouche reste sur son propre phonème</translation>
    </message>
    <message>
        <source>How far the shape is reached at the phoneme&apos;s centre (0 … 1)</source>
        <translation>Dans quelle mesure la forme est atteinte au centre du phonème (0 … 1)</translation>
    </message>
    <message>
        <source>How far the shape reaches past its phoneme, as a share of the phoneme&apos;s length on each side (0 … 2)</source>
        <translation>Jusqu’où la forme déborde de son phonème, en fraction de la durée du phonème de chaque côté (0 … 2)</translation>
    </message>
    <message>
        <source>Load…</source>
        <translation>Charger…</translation>
    </message>
    <message>
        <source>Save…</source>
        <translation>Enregistrer…</translation>
    </message>
    <message>
        <source>Load Visemes</source>
        <translation>Charger des visèmes</translation>
    </message>
    <message>
        <source>Viseme sets (*.json)</source>
        <translation>Jeux de visèmes (*.json)</translation>
    </message>
    <message>
        <source>Save Visemes</source>
        <translation>Enregistrer les visèmes</translation>
    </message>
    <message>
        <source>Shows as (MPEG-4)</source>
        <translation>Apparaît comme (MPEG-4)</translation>
    </message>
    <message>
        <source>The MPEG-4 viseme (1 … 14) the face shows this one as; 0 keeps the mouth at rest</source>
        <translation>Le visème MPEG-4 (1 … 14) que le visage montre pour celui-ci ; 0 laisse la bouche au repos</translation>
    </message>
    <message>
        <source>Start again from a built-in set: MPEG-4&apos;s 14, Oculus Lipsync&apos;s 15 or Microsoft&apos;s SAPI 21</source>
        <translation>Repartir d’un jeu intégré : les 14 de MPEG-4, les 15 d’Oculus Lipsync ou les 21 de SAPI de Microsoft</translation>
    </message>
    <message>
        <source>MPEG-4 (14)</source>
        <translation>MPEG-4 (14)</translation>
    </message>
    <message>
        <source>Oculus (15)</source>
        <translation>Oculus (15)</translation>
    </message>
    <message>
        <source>SAPI (21)</source>
        <translation>SAPI (21)</translation>
    </message>
    <message>
        <source>Built-in:</source>
        <translation>Intégré :</translation>
    </message>
</context>
<context>
    <name>thespis::editor::newDocument</name>
    <message>
        <source>New scenario</source>
        <translation>Nouveau scénario</translation>
    </message>
    <message>
        <source>Actor</source>
        <translation>Acteur</translation>
    </message>
</context>
<context>
    <name>thespis::studio::MainWindow</name>
    <message>
        <source>&amp;Open…</source>
        <translation>&amp;Ouvrir…</translation>
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
    <message>
        <source>Open Scenario</source>
        <translation>Ouvrir un scénario</translation>
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
    <message>
        <source>&amp;New</source>
        <translation>&amp;Nouveau</translation>
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
        <source>&amp;Undo</source>
        <translation>&amp;Annuler</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Rétablir</translation>
    </message>
    <message>
        <source>Go to &amp;End</source>
        <translation>Aller à la &amp;fin</translation>
    </message>
    <message>
        <source>Previous &amp;Frame</source>
        <translation>Image &amp;précédente</translation>
    </message>
    <message>
        <source>&amp;Next Frame</source>
        <translation>Image &amp;suivante</translation>
    </message>
    <message>
        <source>&amp;Preferences…</source>
        <translation>&amp;Préférences…</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>Fichiers ré&amp;cents</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>É&amp;dition</translation>
    </message>
    <message>
        <source>Timeline</source>
        <translation>Ligne temporelle</translation>
    </message>
    <message>
        <source>Curve Editor</source>
        <translation>Éditeur de courbes</translation>
    </message>
    <message>
        <source>Properties</source>
        <translation>Propriétés</translation>
    </message>
    <message>
        <source>Segments</source>
        <translation>Segments</translation>
    </message>
    <message>
        <source>Bake</source>
        <translation>Précalcul</translation>
    </message>
    <message>
        <source>Clip Library</source>
        <translation>Bibliothèque de clips</translation>
    </message>
    <message>
        <source>Gesticon</source>
        <translation>Gesticon</translation>
    </message>
    <message>
        <source>%1[*] — Thespis Studio</source>
        <translation>%1[*] — Thespis Studio</translation>
    </message>
    <message>
        <source>Could not start a new scenario.</source>
        <translation>Impossible de commencer un nouveau scénario.</translation>
    </message>
    <message>
        <source>Could not save “%1”.</source>
        <translation>Impossible d’enregistrer « %1 ».</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>Enregistré : %1</translation>
    </message>
    <message>
        <source>Save Scenario As</source>
        <translation>Enregistrer le scénario sous</translation>
    </message>
    <message>
        <source>Thespis scenarios (*.thespis)</source>
        <translation>Scénarios Thespis (*.thespis)</translation>
    </message>
    <message>
        <source>Unsaved Changes</source>
        <translation>Modifications non enregistrées</translation>
    </message>
    <message>
        <source>“%1” has changes that are not saved. Save them?</source>
        <translation>« %1 » contient des modifications non enregistrées. Les enregistrer ?</translation>
    </message>
    <message>
        <source>an unsaved scenario</source>
        <translation>un scénario non enregistré</translation>
    </message>
    <message>
        <source>Recover Unsaved Work</source>
        <translation>Récupérer le travail non enregistré</translation>
    </message>
    <message>
        <source>Thespis Studio did not close properly. Recover the changes to %1 autosaved at %2?</source>
        <translation>Thespis Studio ne s’est pas fermé correctement. Récupérer les modifications de %1 enregistrées automatiquement à %2 ?</translation>
    </message>
    <message>
        <source>Recovered %1; save it to keep it.</source>
        <translation>Récupéré : %1 ; enregistrez pour le conserver.</translation>
    </message>
    <message>
        <source>Could not recover %1.</source>
        <translation>Impossible de récupérer %1.</translation>
    </message>
    <message>
        <source>Main Toolbar</source>
        <translation>Barre d’outils principale</translation>
    </message>
    <message>
        <source>Start a new scenario: empty, or with one character standing</source>
        <translation>Commencer un nouveau scénario : vide, ou avec un personnage debout</translation>
    </message>
    <message>
        <source>&amp;Character</source>
        <translation>&amp;Personnage</translation>
    </message>
    <message>
        <source>Messages</source>
        <translation>Messages</translation>
    </message>
    <message>
        <source>Messages (%1)</source>
        <translation>Messages (%1)</translation>
    </message>
    <message numerus="yes">
        <source>%n warning(s): see Messages.</source>
        <translation>
            <numerusform>%n avertissement : voir Messages.</numerusform>
            <numerusform>%n avertissements : voir Messages.</numerusform>
        </translation>
    </message>
    <message>
        <source>New Scenario</source>
        <translation>Nouveau scénario</translation>
    </message>
    <message>
        <source>What should the new scenario start with?</source>
        <translation>Par quoi le nouveau scénario doit-il commencer ?</translation>
    </message>
    <message>
        <source>Either way, File ▸ Import Motion… brings in motion capture, Character ▸ Add Character… more characters, and View ▸ Lighting… a light probe.</source>
        <translation>Dans les deux cas, Fichier ▸ Importer un mouvement… ajoute de la capture de mouvement, Personnage ▸ Ajouter un personnage… d’autres personnages, et Affichage ▸ Éclairage… une sonde de lumière.</translation>
    </message>
    <message>
        <source>One Character, Standing</source>
        <translation>Un personnage debout</translation>
    </message>
    <message>
        <source>Empty</source>
        <translation>Vide</translation>
    </message>
    <message>
        <source>Script</source>
        <translation>Script</translation>
    </message>
    <message>
        <source>The script ran to its end.</source>
        <translation>Le script s’est exécuté jusqu’au bout.</translation>
    </message>
    <message>
        <source>Script: %1</source>
        <translation>Script : %1</translation>
    </message>
    <message>
        <source>Run Scripts From This File?</source>
        <translation>Exécuter les scripts de ce fichier ?</translation>
    </message>
    <message>
        <source>“%1” keeps Python scripts. A script can do anything your user account can: read, change and delete files, or use the network.

Run the scenario&apos;s scripts only if you trust where this file came from. Your answer is remembered for this file as it is now.</source>
        <translation>« %1 » contient des scripts Python. Un script peut faire tout ce que votre compte utilisateur peut faire : lire, modifier et supprimer des fichiers, ou utiliser le réseau.

N’exécutez les scripts du scénario que si vous faites confiance à la provenance de ce fichier. Votre réponse est retenue pour ce fichier tel qu’il est maintenant.</translation>
    </message>
    <message>
        <source>Trust This File and Run</source>
        <translation>Faire confiance à ce fichier et exécuter</translation>
    </message>
    <message>
        <source>Posture PCs</source>
        <translation>CP de posture</translation>
    </message>
    <message>
        <source>AR Preview</source>
        <translation>Aperçu RA</translation>
    </message>
    <message>
        <source>Write the scenario and every file it names into one package (.thespkg)</source>
        <translation>Écrire le scénario et tous les fichiers qu’il nomme dans un paquet (.thespkg)</translation>
    </message>
    <message>
        <source>Open a scenario file (.thespis) or a package (.thespkg)</source>
        <translation>Ouvrir un fichier de scénario (.thespis) ou un paquet (.thespkg)</translation>
    </message>
    <message>
        <source>Thespis scenarios and packages (*.thespis *.thespkg);;All files (*)</source>
        <translation>Scénarios et paquets Thespis (*.thespis *.thespkg);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <source>Exported %1</source>
        <translation>%1 exporté</translation>
    </message>
    <message>
        <source>Write a character&apos;s motion as glTF (.glb, with the character) or BVH, for Blender, three.js and game engines</source>
        <translation>Écrire le mouvement d&apos;un personnage en glTF (.glb, avec le personnage) ou BVH, pour Blender, three.js et les moteurs de jeu</translation>
    </message>
    <message>
        <source>&amp;Package…</source>
        <translation>&amp;Paquet…</translation>
    </message>
    <message>
        <source>&amp;Motion (glTF or BVH)…</source>
        <translation>&amp;Mouvement (glTF ou BVH)…</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>E&amp;xporter</translation>
    </message>
    <message>
        <source>&amp;Close-up</source>
        <translation>&amp;Gros plan</translation>
    </message>
    <message>
        <source>This character has no head to frame.</source>
        <translation>Ce personnage n’a pas de tête à cadrer.</translation>
    </message>
    <message>
        <source>No characters</source>
        <translation>Aucun personnage</translation>
    </message>
    <message>
        <source>Masks</source>
        <translation>Masques</translation>
    </message>
    <message>
        <source>Face Pose</source>
        <translation>Pose du visage</translation>
    </message>
    <message>
        <source>Speech</source>
        <translation>Parole</translation>
    </message>
    <message>
        <source>Conversation</source>
        <translation>Conversation</translation>
    </message>
</context>
<context>
    <name>thespis::studio::PreferencesDialog</name>
    <message>
        <source>Preferences</source>
        <translation>Préférences</translation>
    </message>
    <message>
        <source>System default (%1)</source>
        <translation>Par défaut du système (%1)</translation>
    </message>
    <message>
        <source>&amp;Language:</source>
        <translation>&amp;Langue :</translation>
    </message>
    <message>
        <source>The new language is used from the next start of the studio.</source>
        <translation>La nouvelle langue sera utilisée au prochain démarrage du studio.</translation>
    </message>
    <message>
        <source> min</source>
        <translation> min</translation>
    </message>
    <message>
        <source>How often open work is copied to a recovery file, offered after a crash</source>
        <translation>Fréquence de copie du travail ouvert dans un fichier de récupération, proposé après un plantage</translation>
    </message>
    <message>
        <source>&amp;Autosave every:</source>
        <translation>Enregistrement &amp;automatique toutes les :</translation>
    </message>
</context>
<context>
    <name>thespis::widgets::CurveView</name>
    <message>
        <source>No curves to show</source>
        <translation>Aucune courbe à afficher</translation>
    </message>
    <message>
        <source>Click a key to select it, drag to move it; double-click a curve to add a key. Wheel: zoom (Ctrl: values only, Shift: time only); middle-drag: pan; F: frame all.</source>
        <translation>Cliquez sur une clé pour la sélectionner, faites-la glisser pour la déplacer ; double-cliquez sur une courbe pour ajouter une clé. Molette : zoom (Ctrl : valeurs seules, Maj : temps seul) ; glisser avec le bouton du milieu : déplacer la vue ; F : tout cadrer.</translation>
    </message>
    <message>
        <source>Tangents</source>
        <translation>Tangentes</translation>
    </message>
    <message>
        <source>Auto Clamped</source>
        <translation>Auto limitée</translation>
    </message>
    <message>
        <source>Linear</source>
        <translation>Linéaire</translation>
    </message>
    <message>
        <source>Constant</source>
        <translation>Constante</translation>
    </message>
    <message>
        <source>Free</source>
        <translation>Libre</translation>
    </message>
    <message>
        <source>Broken</source>
        <translation>Brisée</translation>
    </message>
    <message>
        <source>Smooth tangents that never overshoot neighbouring keys</source>
        <translation>Tangentes lisses qui ne dépassent jamais les clés voisines</translation>
    </message>
    <message>
        <source>Straight lines between keys</source>
        <translation>Lignes droites entre les clés</translation>
    </message>
    <message>
        <source>Hold the value until the next key</source>
        <translation>Maintenir la valeur jusqu’à la clé suivante</translation>
    </message>
    <message>
        <source>Smooth tangents you drag, the same on both sides</source>
        <translation>Tangentes lisses à faire glisser, identiques des deux côtés</translation>
    </message>
    <message>
        <source>Tangents you drag, each side on its own</source>
        <translation>Tangentes à faire glisser, chaque côté indépendamment</translation>
    </message>
    <message>
        <source>Delete Keys</source>
        <translation>Supprimer les clés</translation>
    </message>
    <message>
        <source>Frame All</source>
        <translation>Tout cadrer</translation>
    </message>
    <message>
        <source>%1, key %2
Time %3 s, value %4
Tangents: %5</source>
        <translation>%1, clé %2
Temps %3 s, valeur %4
Tangentes : %5</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>Δt %1 s   Δv %2</source>
        <translation>Δt %1 s   Δv %2</translation>
    </message>
</context>
<context>
    <name>thespis::widgets::JointMaskView</name>
    <message>
        <source>No skeleton</source>
        <translation>Aucun squelette</translation>
    </message>
    <message>
        <source>R</source>
        <comment>the character&apos;s right side</comment>
        <translation>D</translation>
    </message>
    <message>
        <source>L</source>
        <comment>the character&apos;s left side</comment>
        <translation>G</translation>
    </message>
    <message>
        <source>Drag to paint · right-drag paints 0</source>
        <translation>Glisser pour peindre · glisser avec le bouton droit peint 0</translation>
    </message>
    <message>
        <source>Joint</source>
        <translation>Articulation</translation>
    </message>
    <message>
        <source>Weight</source>
        <translation>Poids</translation>
    </message>
    <message>
        <source>Brush weight</source>
        <translation>Poids du pinceau</translation>
    </message>
    <message>
        <source>The weight a left-button stroke paints (the right button paints 0)</source>
        <translation>Le poids peint par un trait du bouton gauche (le bouton droit peint 0)</translation>
    </message>
    <message>
        <source>Radius</source>
        <translation>Rayon</translation>
    </message>
    <message>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <source>Radius of the brush in the picture</source>
        <translation>Rayon du pinceau dans l’image</translation>
    </message>
    <message>
        <source>%1: set by the mask</source>
        <translation>%1 : défini par le masque</translation>
    </message>
    <message>
        <source>%1: inherited</source>
        <translation>%1 : hérité</translation>
    </message>
    <message>
        <source>Set to 1</source>
        <translation>Mettre à 1</translation>
    </message>
    <message>
        <source>Set to 0.5</source>
        <translation>Mettre à 0,5</translation>
    </message>
    <message>
        <source>Set to 0</source>
        <translation>Mettre à 0</translation>
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
    <name>thespis::widgets::TimelineView</name>
    <message>
        <source>%1 fps</source>
        <translation>%1 i/s</translation>
    </message>
    <message>
        <source>Remove Marker “%1”</source>
        <translation>Supprimer le marqueur « %1 »</translation>
    </message>
    <message>
        <source>Add Marker Here</source>
        <translation>Ajouter un marqueur ici</translation>
    </message>
    <message>
        <source>%1
%2 – open end</source>
        <translation>%1
%2 – fin ouverte</translation>
    </message>
    <message>
        <source>%1
%2 – %3 (%4)</source>
        <translation>%1
%2 – %3 (%4)</translation>
    </message>
    <message>
        <source>The track is locked</source>
        <translation>La piste est verrouillée</translation>
    </message>
    <message>
        <source>Mute: leave this track out of playback</source>
        <translation>Désactiver : exclure cette piste de la lecture</translation>
    </message>
    <message>
        <source>Solo: play only the soloed tracks</source>
        <translation>Solo : ne lire que les pistes en solo</translation>
    </message>
    <message>
        <source>Lock: protect this track&apos;s clips from edits</source>
        <translation>Verrouiller : protéger les clips de cette piste des modifications</translation>
    </message>
    <message>
        <source>%1 at %2</source>
        <translation>%1 à %2</translation>
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
    <message>
        <source>Previous frame (Left arrow)</source>
        <translation>Image précédente (Flèche gauche)</translation>
    </message>
    <message>
        <source>Next frame (Right arrow)</source>
        <translation>Image suivante (Flèche droite)</translation>
    </message>
    <message>
        <source>Go to the end (End)</source>
        <translation>Aller à la fin (Fin)</translation>
    </message>
    <message>
        <source>Frames per second for frame numbers, frame steps and snapping</source>
        <translation>Images par seconde pour les numéros d’image, l’avance image par image et l’aimantation</translation>
    </message>
    <message>
        <source>%1 fps</source>
        <translation>%1 i/s</translation>
    </message>
</context>
</TS>

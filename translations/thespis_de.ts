<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>CharacterChoice</name>
    <message>
        <source>Character:</source>
        <translation>Figur:</translation>
    </message>
</context>
<context>
    <name>Microphone</name>
    <message>
        <source>There is no microphone.</source>
        <translation>Es gibt kein Mikrofon.</translation>
    </message>
    <message>
        <source>The microphone “%1” did not open (Qt Multimedia error %2).</source>
        <translation>Das Mikrofon „%1“ ließ sich nicht öffnen (Qt-Multimedia-Fehler %2).</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Thespis Studio: author and preview virtual humans. Opens SCENARIO, or the built-in demo.</source>
        <translation>Thespis Studio: virtuelle Menschen gestalten und ansehen. Öffnet SZENARIO oder die eingebaute Demo.</translation>
    </message>
    <message>
        <source>The scenario file (.thespis) to open.</source>
        <translation>Die zu öffnende Szenariodatei (.thespis).</translation>
    </message>
    <message>
        <source>Start at SECONDS into the scenario.</source>
        <translation>Bei SEKUNDEN im Szenario beginnen.</translation>
    </message>
    <message>
        <source>Save a picture of the window to FILE (PNG) once the scenario is shown, then quit.</source>
        <translation>Ein Bild des Fensters als DATEI (PNG) speichern, sobald das Szenario angezeigt wird, dann beenden.</translation>
    </message>
</context>
<context>
    <name>thespis::editor::ArCalibrationDialog</name>
    <message>
        <source>Calibrate the Camera</source>
        <translation>Kamera kalibrieren</translation>
    </message>
    <message>
        <source>chessboard:COLUMNSxROWS:SQUARE (inner corners, metres) or charuco:DICTIONARY:COLUMNSxROWS:SQUARE:MARKER</source>
        <translation>chessboard:SPALTENxZEILEN:FELD (innere Ecken, Meter) oder charuco:WÖRTERBUCH:SPALTENxZEILEN:FELD:MARKER</translation>
    </message>
    <message>
        <source>Square pixels (fx = fy)</source>
        <translation>Quadratische Pixel (fx = fy)</translation>
    </message>
    <message>
        <source>Capture View</source>
        <translation>Ansicht aufnehmen</translation>
    </message>
    <message>
        <source>Keep the picture shown as a view of the board; hold the board at many angles</source>
        <translation>Das gezeigte Bild als Ansicht des Musters behalten; das Muster in vielen Winkeln halten</translation>
    </message>
    <message>
        <source>Add Photos…</source>
        <translation>Fotos hinzufügen…</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <source>Calibrate</source>
        <translation>Kalibrieren</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Not calibrating</source>
        <translation>Keine Kalibrierung läuft</translation>
    </message>
    <message>
        <source>Save Camera File…</source>
        <translation>Kameradatei speichern…</translation>
    </message>
    <message>
        <source>Board:</source>
        <translation>Muster:</translation>
    </message>
    <message>
        <source>Views of the board:</source>
        <translation>Ansichten des Musters:</translation>
    </message>
    <message>
        <source>Choose Photos of the Board</source>
        <translation>Fotos des Musters wählen</translation>
    </message>
    <message>
        <source>Pictures (*.png *.jpg *.jpeg *.bmp *.tif *.tiff)</source>
        <translation>Bilder (*.png *.jpg *.jpeg *.bmp *.tif *.tiff)</translation>
    </message>
    <message>
        <source>Save the Camera File</source>
        <translation>Kameradatei speichern</translation>
    </message>
    <message>
        <source>Camera files (*.yml *.yaml *.xml *.json)</source>
        <translation>Kameradateien (*.yml *.yaml *.xml *.json)</translation>
    </message>
    <message>
        <source>The camera file could not be written: %1</source>
        <translation>Die Kameradatei konnte nicht geschrieben werden: %1</translation>
    </message>
    <message>
        <source>No picture</source>
        <translation>Kein Bild</translation>
    </message>
    <message>
        <source>The test pattern shows the board typed here: fix its spec.</source>
        <translation>Das Testbild zeigt das hier eingegebene Muster: Beschreibung korrigieren.</translation>
    </message>
    <message>
        <source>No live picture</source>
        <translation>Kein Livebild</translation>
    </message>
    <message>
        <source>%1
Add photos of the board instead.</source>
        <translation>%1
Stattdessen Fotos des Musters hinzufügen.</translation>
    </message>
    <message>
        <source>Waiting for the first picture…</source>
        <translation>Warte auf das erste Bild…</translation>
    </message>
    <message>
        <source>Hold the board at many angles, filling the picture</source>
        <translation>Das Muster in vielen Winkeln halten, bildfüllend</translation>
    </message>
    <message numerus="yes">
        <source>%n view(s) so far</source>
        <translation>
            <numerusform>%n Ansicht bisher</numerusform>
            <numerusform>%n Ansichten bisher</numerusform>
        </translation>
    </message>
    <message>
        <source>Ended</source>
        <translation>Zu Ende</translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation>Angehalten</translation>
    </message>
    <message>
        <source>The view could not be kept in %1.</source>
        <translation>Die Ansicht konnte nicht in %1 abgelegt werden.</translation>
    </message>
    <message>
        <source>An ArUco grid is for tracking only: calibrate with a chessboard or a ChArUco board.</source>
        <translation>Ein ArUco-Raster dient nur dem Tracking: mit einem Schachbrett oder einem ChArUco-Muster kalibrieren.</translation>
    </message>
    <message numerus="yes">
        <source>Calibrating from %n view(s)…</source>
        <translation>
            <numerusform>Kalibriere aus %n Ansicht…</numerusform>
            <numerusform>Kalibriere aus %n Ansichten…</numerusform>
        </translation>
    </message>
    <message>
        <source>Calibrating</source>
        <translation>Kalibrieren</translation>
    </message>
    <message>
        <source>Finding the board</source>
        <translation>Muster suchen</translation>
    </message>
    <message>
        <source>%1: %2 / %3</source>
        <translation>%1: %2 / %3</translation>
    </message>
    <message>
        <source>%1 — %2 px</source>
        <translation>%1 — %2 px</translation>
    </message>
    <message>
        <source>%1 — found</source>
        <translation>%1 — gefunden</translation>
    </message>
    <message>
        <source>%1 — board not found</source>
        <translation>%1 — Muster nicht gefunden</translation>
    </message>
    <message>
        <source>Cancelled</source>
        <translation>Abgebrochen</translation>
    </message>
    <message>
        <source>Failed</source>
        <translation>Fehlgeschlagen</translation>
    </message>
    <message>
        <source>Cancelled.</source>
        <translation>Abgebrochen.</translation>
    </message>
    <message>
        <source>Done</source>
        <translation>Fertig</translation>
    </message>
    <message>
        <source>RMS reprojection error %1 px over %2 of %3 views, %4 × %5.
fx %6 ± %7, fy %8 ± %9, centre (%10, %11) px.</source>
        <translation>RMS-Rückprojektionsfehler %1 px über %2 von %3 Ansichten, %4 × %5.
fx %6 ± %7, fy %8 ± %9, Mitte (%10, %11) px.</translation>
    </message>
    <message>
        <source>Calibrate first.</source>
        <translation>Zuerst kalibrieren.</translation>
    </message>
    <message>
        <source>At least %1 views of the board are needed</source>
        <translation>Mindestens %1 Ansichten des Musters sind nötig</translation>
    </message>
</context>
<context>
    <name>thespis::editor::ArPreviewPanel</name>
    <message>
        <source>Test pattern (a synthetic board)</source>
        <translation>Testbild (ein synthetisches Muster)</translation>
    </message>
    <message>
        <source>Video file</source>
        <translation>Videodatei</translation>
    </message>
    <message>
        <source>Folder of pictures</source>
        <translation>Bilderordner</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>Kamera</translation>
    </message>
    <message>
        <source>A board moving as if hand-held, seen by a known camera: nothing to print or calibrate. It shows the target&apos;s board.</source>
        <translation>Ein wie von Hand gehaltenes, bewegtes Muster, gesehen von einer bekannten Kamera: nichts zu drucken oder zu kalibrieren. Es zeigt das Muster des Ziels.</translation>
    </message>
    <message>
        <source>No video chosen</source>
        <translation>Kein Video gewählt</translation>
    </message>
    <message>
        <source>Choose…</source>
        <translation>Wählen…</translation>
    </message>
    <message>
        <source>Choose a Video</source>
        <translation>Video wählen</translation>
    </message>
    <message>
        <source>Videos (*.mp4 *.avi *.mov *.mkv *.webm);;All files (*)</source>
        <translation>Videos (*.mp4 *.avi *.mov *.mkv *.webm);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>No folder chosen</source>
        <translation>Kein Ordner gewählt</translation>
    </message>
    <message>
        <source> fps</source>
        <translation> B/s</translation>
    </message>
    <message>
        <source>How many pictures a second the folder plays</source>
        <translation>Wie viele Bilder pro Sekunde der Ordner abspielt</translation>
    </message>
    <message>
        <source>Choose a Folder of Pictures</source>
        <translation>Bilderordner wählen</translation>
    </message>
    <message>
        <source>Rescan</source>
        <translation>Neu suchen</translation>
    </message>
    <message>
        <source>Look for cameras again (after plugging one in)</source>
        <translation>Erneut nach Kameras suchen (nach dem Anstecken einer Kamera)</translation>
    </message>
    <message>
        <source>No camera file chosen</source>
        <translation>Keine Kameradatei gewählt</translation>
    </message>
    <message>
        <source>The camera&apos;s intrinsics as OpenCV writes them (.yml, .yaml, .xml, .json)</source>
        <translation>Die inneren Parameter der Kamera, wie OpenCV sie schreibt (.yml, .yaml, .xml, .json)</translation>
    </message>
    <message>
        <source>Calibrate…</source>
        <translation>Kalibrieren…</translation>
    </message>
    <message>
        <source>Calibrate the camera from views of a chessboard or a ChArUco board</source>
        <translation>Die Kamera aus Ansichten eines Schachbretts oder eines ChArUco-Musters kalibrieren</translation>
    </message>
    <message>
        <source>Choose a Camera File</source>
        <translation>Kameradatei wählen</translation>
    </message>
    <message>
        <source>Camera files (*.yml *.yaml *.xml *.json);;All files (*)</source>
        <translation>Kameradateien (*.yml *.yaml *.xml *.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Board:</source>
        <translation>Muster:</translation>
    </message>
    <message>
        <source>Picture:</source>
        <translation>Bild:</translation>
    </message>
    <message>
        <source>aruco-grid:DICTIONARY:COLUMNSxROWS:MARKER:GAP or charuco:DICTIONARY:COLUMNSxROWS:SQUARE:MARKER, lengths in metres</source>
        <translation>aruco-grid:WÖRTERBUCH:SPALTENxZEILEN:MARKER:ABSTAND oder charuco:WÖRTERBUCH:SPALTENxZEILEN:FELD:MARKER, Längen in Metern</translation>
    </message>
    <message>
        <source>A printed picture (PNG, JPEG)</source>
        <translation>Ein gedrucktes Bild (PNG, JPEG)</translation>
    </message>
    <message>
        <source> m wide</source>
        <translation> m breit</translation>
    </message>
    <message>
        <source>Printed:</source>
        <translation>Gedruckt:</translation>
    </message>
    <message>
        <source>Choose the Printed Picture</source>
        <translation>Gedrucktes Bild wählen</translation>
    </message>
    <message>
        <source>Pictures (*.png *.jpg *.jpeg *.bmp)</source>
        <translation>Bilder (*.png *.jpg *.jpeg *.bmp)</translation>
    </message>
    <message>
        <source>Of life size: 0.1 stands a 1.8 m character 18 cm tall on a desk</source>
        <translation>Der Lebensgröße: 0,1 stellt eine 1,8 m große Figur 18 cm hoch auf einen Tisch</translation>
    </message>
    <message>
        <source>How far the world turns about the target&apos;s normal</source>
        <translation>Wie weit sich die Welt um die Normale des Ziels dreht</translation>
    </message>
    <message>
        <source> m</source>
        <translation> m</translation>
    </message>
    <message>
        <source>Where the world&apos;s origin is on the target, from its centre along its own axes</source>
        <translation>Wo der Ursprung der Welt auf dem Ziel liegt, von seiner Mitte entlang seiner eigenen Achsen</translation>
    </message>
    <message>
        <source>Shadows on the real ground</source>
        <translation>Schatten auf dem echten Boden</translation>
    </message>
    <message>
        <source>Scale:</source>
        <translation>Maßstab:</translation>
    </message>
    <message>
        <source>Heading:</source>
        <translation>Drehung:</translation>
    </message>
    <message>
        <source>Offset:</source>
        <translation>Versatz:</translation>
    </message>
    <message>
        <source>Show AR Shadows</source>
        <translation>AR-Schatten zeigen</translation>
    </message>
    <message>
        <source>Hide AR Shadows</source>
        <translation>AR-Schatten ausblenden</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>No camera found</source>
        <translation>Keine Kamera gefunden</translation>
    </message>
    <message>
        <source>No camera found: plug one in and press Rescan, or choose a video file or the test pattern.</source>
        <translation>Keine Kamera gefunden: eine anstecken und „Neu suchen“ drücken, oder eine Videodatei oder das Testbild wählen.</translation>
    </message>
    <message>
        <source>Choose a video file.</source>
        <translation>Eine Videodatei wählen.</translation>
    </message>
    <message>
        <source>Choose a folder of pictures.</source>
        <translation>Einen Bilderordner wählen.</translation>
    </message>
    <message>
        <source>, %1 fps</source>
        <translation>, %1 B/s</translation>
    </message>
    <message>
        <source>, %1 frames (%2 s)</source>
        <translation>, %1 Bilder (%2 s)</translation>
    </message>
    <message>
        <source>, %1 frames</source>
        <translation>, %1 Bilder</translation>
    </message>
    <message>
        <source>This camera file cannot be used: %1</source>
        <translation>Diese Kameradatei ist nicht verwendbar: %1</translation>
    </message>
    <message>
        <source>The test pattern&apos;s camera is known exactly: no file needed.</source>
        <translation>Die Kamera des Testbilds ist genau bekannt: keine Datei nötig.</translation>
    </message>
    <message>
        <source>The camera file is for %1 pictures, but the source gives %2: calibrate the camera at the size it films at.</source>
        <translation>Die Kameradatei gilt für Bilder von %1, die Quelle liefert aber %2: die Kamera in der Größe kalibrieren, in der sie filmt.</translation>
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
        <translation>Die Kameradatei der Kamera wählen, die es gefilmt hat, oder eine kalibrieren.</translation>
    </message>
    <message>
        <source>The board spec does not parse: %1</source>
        <translation>Die Musterbeschreibung ist ungültig: %1</translation>
    </message>
    <message>
        <source>A chessboard calibrates a camera but cannot be tracked: use an ArUco grid or a ChArUco board.</source>
        <translation>Ein Schachbrett kalibriert eine Kamera, kann aber nicht verfolgt werden: ein ArUco-Raster oder ein ChArUco-Muster verwenden.</translation>
    </message>
    <message>
        <source>ArUco grid, %1 × %2 markers of %3 cm, %4 × %5 cm in all</source>
        <translation>ArUco-Raster, %1 × %2 Marker zu %3 cm, insgesamt %4 × %5 cm</translation>
    </message>
    <message>
        <source>ChArUco board, %1 × %2 squares of %3 cm</source>
        <translation>ChArUco-Muster, %1 × %2 Felder zu %3 cm</translation>
    </message>
    <message>
        <source>Choose the printed picture to track.</source>
        <translation>Das zu verfolgende gedruckte Bild wählen.</translation>
    </message>
    <message>
        <source>%1: no such picture.</source>
        <translation>%1: kein solches Bild.</translation>
    </message>
    <message>
        <source>The test pattern shows a board: track a board with it.</source>
        <translation>Das Testbild zeigt ein Muster: damit ein Muster verfolgen.</translation>
    </message>
    <message>
        <source>%1, %2 m wide</source>
        <translation>%1, %2 m breit</translation>
    </message>
    <message>
        <source>Source</source>
        <translation>Quelle</translation>
    </message>
    <message>
        <source>Target</source>
        <translation>Ziel</translation>
    </message>
    <message>
        <source>Placement on the Target</source>
        <translation>Platzierung auf dem Ziel</translation>
    </message>
    <message>
        <source>Preview</source>
        <translation>Vorschau</translation>
    </message>
    <message>
        <source>Light from a mirror ball in view</source>
        <translation>Licht aus einer Spiegelkugel im Bild</translation>
    </message>
    <message>
        <source>Find a chrome ball in the picture and light the characters with what it mirrors</source>
        <translation>Eine Chromkugel im Bild finden und die Figuren mit dem beleuchten, was sie spiegelt</translation>
    </message>
    <message>
        <source>Smooth edges (slower)</source>
        <translation>Glatte Kanten (langsamer)</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Starten</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Anhalten</translation>
    </message>
    <message>
        <source>Record…</source>
        <translation>Aufnehmen…</translation>
    </message>
    <message>
        <source>Write what the preview shows to a video (.mp4 or .avi)</source>
        <translation>Was die Vorschau zeigt, als Video schreiben (.mp4 oder .avi)</translation>
    </message>
    <message>
        <source>Record the AR Preview</source>
        <translation>AR-Vorschau aufnehmen</translation>
    </message>
    <message>
        <source>Videos (*.mp4 *.avi)</source>
        <translation>Videos (*.mp4 *.avi)</translation>
    </message>
    <message>
        <source>Place the World on the Target</source>
        <translation>Welt auf dem Ziel platzieren</translation>
    </message>
    <message>
        <source>Cannot start</source>
        <translation>Start nicht möglich</translation>
    </message>
    <message>
        <source>Starting…</source>
        <translation>Starte…</translation>
    </message>
    <message>
        <source>Reading the first frames and preparing the scene.</source>
        <translation>Die ersten Bilder werden gelesen und die Szene vorbereitet.</translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation>Angehalten</translation>
    </message>
    <message>
        <source>Press Start to go on.</source>
        <translation>„Starten“ drücken, um fortzufahren.</translation>
    </message>
    <message>
        <source>%1 fps</source>
        <translation>%1 B/s</translation>
    </message>
    <message>
        <source>latency %1 ms</source>
        <translation>Latenz %1 ms</translation>
    </message>
    <message numerus="yes">
        <source>Tracking: %n feature(s)</source>
        <translation>
            <numerusform>Verfolgt: %n Merkmal</numerusform>
            <numerusform>Verfolgt: %n Merkmale</numerusform>
        </translation>
    </message>
    <message>
        <source>Target lost: holding its last place</source>
        <translation>Ziel verloren: letzte Lage wird gehalten</translation>
    </message>
    <message>
        <source>Searching for the target…</source>
        <translation>Suche das Ziel…</translation>
    </message>
    <message>
        <source>frame %1</source>
        <translation>Bild %1</translation>
    </message>
    <message>
        <source>dropped: %1</source>
        <translation>verworfen: %1</translation>
    </message>
    <message>
        <source>lit by the mirror ball</source>
        <translation>von der Spiegelkugel beleuchtet</translation>
    </message>
    <message>
        <source>REC</source>
        <translation>REC</translation>
    </message>
    <message>
        <source>Ended</source>
        <translation>Zu Ende</translation>
    </message>
    <message>
        <source>%1.
Press Start to play it again.</source>
        <translation>%1.
„Starten“ drücken, um es erneut abzuspielen.</translation>
    </message>
    <message>
        <source>Stopped by a problem</source>
        <translation>Wegen eines Problems angehalten</translation>
    </message>
    <message>
        <source>%1
Fix it, then press Start.</source>
        <translation>%1
Beheben, dann „Starten“ drücken.</translation>
    </message>
    <message>
        <source>Recorded to %1.</source>
        <translation>Aufgenommen in %1.</translation>
    </message>
    <message>
        <source>Start the preview first, then record it.</source>
        <translation>Zuerst die Vorschau starten, dann aufnehmen.</translation>
    </message>
    <message>
        <source>Cannot record: %1</source>
        <translation>Aufnahme nicht möglich: %1</translation>
    </message>
    <message>
        <source>Recording to %1…</source>
        <translation>Nehme auf in %1…</translation>
    </message>
    <message>
        <source>The recording could not be finished: %1</source>
        <translation>Die Aufnahme konnte nicht abgeschlossen werden: %1</translation>
    </message>
    <message>
        <source>Play the scenario over the video</source>
        <translation>Das Szenario über dem Video abspielen</translation>
    </message>
    <message>
        <source>Stop Recording</source>
        <translation>Aufnahme beenden</translation>
    </message>
    <message>
        <source>AR Preview</source>
        <translation>AR-Vorschau</translation>
    </message>
    <message>
        <source>Press Start to play the scenario over the video.</source>
        <translation>„Starten“ drücken, um das Szenario über dem Video abzuspielen.</translation>
    </message>
    <message>
        <source>mirror ball: %1</source>
        <translation>Spiegelkugel: %1</translation>
    </message>
    <message>
        <source>Mirror ball</source>
        <translation>Spiegelkugel</translation>
    </message>
    <message>
        <source>The picture size asked of the camera; its camera file must be for the same size</source>
        <translation>Die von der Kamera angeforderte Bildgröße; ihre Kameradatei muss für dieselbe Größe sein</translation>
    </message>
    <message>
        <source>Camera file&apos;s size</source>
        <translation>Größe der Kameradatei</translation>
    </message>
    <message>
        <source>Frames a second asked of the camera (it may give fewer in dim light)</source>
        <translation>Von der Kamera angeforderte Bilder pro Sekunde (bei wenig Licht liefert sie eventuell weniger)</translation>
    </message>
    <message>
        <source>The camera file&apos;s size is asked for, at %1 fps.</source>
        <translation>Die Größe der Kameradatei wird angefordert, mit %1 fps.</translation>
    </message>
    <message>
        <source>Plays with the studio&apos;s transport</source>
        <translation>Spielt mit der Transportleiste des Studios</translation>
    </message>
    <message>
        <source>Plays on the video&apos;s time</source>
        <translation>Spielt in der Zeit des Videos</translation>
    </message>
    <message>
        <source>The transport: play, scrub and loop in the studio, and the video shows it. The video&apos;s time: the playhead follows the video frame by frame, as a recording would.</source>
        <translation>Die Transportleiste: Abspielen, Scrubben und Schleifen im Studio, und das Video zeigt es. Die Zeit des Videos: Der Abspielkopf folgt dem Video Bild für Bild, wie eine Aufnahme.</translation>
    </message>
    <message>
        <source>The characters changed, which ended the recording.
Press Start to see them over the video.</source>
        <translation>Die Figuren haben sich geändert, das hat die Aufnahme beendet.
Drücken Sie Start, um sie über dem Video zu sehen.</translation>
    </message>
    <message>
        <source>The characters changed: the preview started again with them.</source>
        <translation>Die Figuren haben sich geändert: die Vorschau ist mit ihnen neu gestartet.</translation>
    </message>
    <message>
        <source>motion blur %1 px</source>
        <translation>Bewegungsunschärfe %1 px</translation>
    </message>
    <message>
        <source>tilt unsure (ratio %1)</source>
        <translation>Neigung unsicher (Verhältnis %1)</translation>
    </message>
    <message>
        <source>Characters look at the camera</source>
        <translation>Die Figuren sehen in die Kamera</translation>
    </message>
    <message>
        <source>Their eyes, heads and chests turn to the real camera as it is tracked: they look at the visitor</source>
        <translation>Augen, Köpfe und Oberkörper wenden sich der echten, verfolgten Kamera zu: Sie sehen den Besucher an</translation>
    </message>
</context>
<context>
    <name>thespis::editor::Autosaver</name>
    <message>
        <source>Autosave failed: %1</source>
        <translation>Automatisches Speichern fehlgeschlagen: %1</translation>
    </message>
</context>
<context>
    <name>thespis::editor::BakePanel</name>
    <message>
        <source>The character whose body is baked</source>
        <translation>Die Figur, deren Körper gebacken wird</translation>
    </message>
    <message>
        <source>Character:</source>
        <translation>Figur:</translation>
    </message>
    <message>
        <source>Uses now:</source>
        <translation>Derzeit verwendet:</translation>
    </message>
    <message>
        <source>Bake Settings</source>
        <translation>Backeinstellungen</translation>
    </message>
    <message>
        <source>Diffuse unshadowed</source>
        <translation>Diffus, unverschattet</translation>
    </message>
    <message>
        <source>Diffuse shadowed</source>
        <translation>Diffus, verschattet</translation>
    </message>
    <message>
        <source>Diffuse shadowed merged (paper)</source>
        <translation>Diffus, verschattet, zusammengeführt (Paper)</translation>
    </message>
    <message>
        <source>DU: no shadows at all</source>
        <translation>DU: überhaupt keine Schatten</translation>
    </message>
    <message>
        <source>DS: each segment shadows only itself</source>
        <translation>DS: jedes Segment verschattet nur sich selbst</translation>
    </message>
    <message>
        <source>DSM: every segment shadows the others; receivers are transparent, occluders are not baked</source>
        <translation>DSM: jedes Segment verschattet die anderen; Empfänger sind transparent, Verdecker werden nicht gebacken</translation>
    </message>
    <message>
        <source>Transfer:</source>
        <translation>Transfer:</translation>
    </message>
    <message>
        <source>Spherical harmonics order: bands 0 … order − 1</source>
        <translation>Ordnung der Kugelflächenfunktionen: Bänder 0 … Ordnung − 1</translation>
    </message>
    <message>
        <source>SH order:</source>
        <translation>SH-Ordnung:</translation>
    </message>
    <message>
        <source>Stratified cosine-weighted directions traced from every vertex</source>
        <translation>Stratifizierte, kosinusgewichtete Richtungen, von jedem Vertex aus verfolgt</translation>
    </message>
    <message>
        <source>Rays per vertex:</source>
        <translation>Strahlen pro Vertex:</translation>
    </message>
    <message>
        <source>Embree</source>
        <translation>Embree</translation>
    </message>
    <message>
        <source>Uniform grid</source>
        <translation>Gleichmäßiges Gitter</translation>
    </message>
    <message>
        <source>The ray tracer: Embree, or the paper&apos;s uniform grid (same results, slower)</source>
        <translation>Der Raytracer: Embree oder das gleichmäßige Gitter aus dem Paper (gleiche Ergebnisse, langsamer)</translation>
    </message>
    <message>
        <source>Ray tracer:</source>
        <translation>Raytracer:</translation>
    </message>
    <message>
        <source>Relaxation ε in metres: hits nearer than this are ignored (default 1.71e-4, the H-Anim segment gap)</source>
        <translation>Relaxation ε in Metern: Näher liegende Treffer werden ignoriert (Standard 1.71e-4, der H-Anim-Segmentabstand)</translation>
    </message>
    <message>
        <source>Relaxation ε (m):</source>
        <translation>Relaxation ε (m):</translation>
    </message>
    <message>
        <source>All (%1)</source>
        <translation>Alle (%1)</translation>
    </message>
    <message>
        <source>Worker threads; the result does not depend on it</source>
        <translation>Arbeits-Threads; das Ergebnis hängt nicht davon ab</translation>
    </message>
    <message>
        <source>Threads:</source>
        <translation>Threads:</translation>
    </message>
    <message>
        <source>Start Bake</source>
        <translation>Backen starten</translation>
    </message>
    <message>
        <source>Bake the character in the background; the result is one undoable step</source>
        <translation>Die Figur im Hintergrund backen; das Ergebnis lässt sich in einem Schritt rückgängig machen</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Stop the bake; nothing changes</source>
        <translation>Das Backen abbrechen; nichts wird geändert</translation>
    </message>
    <message>
        <source>Not baking</source>
        <translation>Kein Backvorgang</translation>
    </message>
    <message>
        <source>Show PRT lighting (off: Phong)</source>
        <translation>PRT-Beleuchtung anzeigen (aus: Phong)</translation>
    </message>
    <message>
        <source>Shade the viewport with the baked transfer, or with plain Phong to compare</source>
        <translation>Die 3D-Ansicht mit dem gebackenen Transfer schattieren oder zum Vergleich mit einfachem Phong</translation>
    </message>
    <message>
        <source>%1 coefficients per vertex</source>
        <translation>%1 Koeffizienten pro Vertex</translation>
    </message>
    <message>
        <source>Relaxation ε must be a distance in metres from 0 to %1 (for example 1.71e-4), not “%2”.</source>
        <translation>Relaxation ε muss ein Abstand in Metern von 0 bis %1 sein (zum Beispiel 1.71e-4), nicht „%2“.</translation>
    </message>
    <message>
        <source>There is no character to bake.</source>
        <translation>Es gibt keine Figur zum Backen.</translation>
    </message>
    <message>
        <source>Save the scenario in a folder you can write to first: the bake goes to %1, which cannot be written.</source>
        <translation>Speichern Sie das Szenario zuerst in einem Ordner mit Schreibrechten: Das Backergebnis wird in %1 abgelegt, und dort kann nicht geschrieben werden.</translation>
    </message>
    <message>
        <source>its folder</source>
        <translation>dem Ordner des Szenarios</translation>
    </message>
    <message>
        <source>The body of the character could not be loaded: %1</source>
        <translation>Der Körper der Figur konnte nicht geladen werden: %1</translation>
    </message>
    <message>
        <source>Baking %1: %2, order %3, %4 rays per vertex…</source>
        <translation>%1 wird gebacken: %2, Ordnung %3, %4 Strahlen pro Vertex…</translation>
    </message>
    <message>
        <source>%p% — %1 / %2 vertices</source>
        <translation>%p% — %1 / %2 Vertices</translation>
    </message>
    <message>
        <source>Cancelled</source>
        <translation>Abgebrochen</translation>
    </message>
    <message>
        <source>Cancelled — nothing changed.</source>
        <translation>Abgebrochen — nichts wurde geändert.</translation>
    </message>
    <message>
        <source>Failed</source>
        <translation>Fehlgeschlagen</translation>
    </message>
    <message>
        <source>The bake failed: %1</source>
        <translation>Das Backen ist fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>The scenario was closed while baking; nothing changed.</source>
        <translation>Das Szenario wurde während des Backens geschlossen; nichts wurde geändert.</translation>
    </message>
    <message>
        <source>The character “%1” is gone; the bake was thrown away.</source>
        <translation>Die Figur „%1“ existiert nicht mehr; das Backergebnis wurde verworfen.</translation>
    </message>
    <message>
        <source>%1 changed while baking (body or segment tags); nothing changed: bake again.</source>
        <translation>%1 wurde während des Backens geändert (Körper oder Segmentmarkierungen); nichts wurde geändert: Bitte erneut backen.</translation>
    </message>
    <message>
        <source>Bake %1 (%2, order %3)</source>
        <translation>%1 backen (%2, Ordnung %3)</translation>
    </message>
    <message>
        <source>The bake could not be applied: %1</source>
        <translation>Das Backergebnis konnte nicht übernommen werden: %1</translation>
    </message>
    <message>
        <source>Last bake: %1, order %2, %3 rays per vertex — %4 s, %5 Mrays/s.</source>
        <translation>Letztes Backen: %1, Ordnung %2, %3 Strahlen pro Vertex — %4 s, %5 Mio. Strahlen/s.</translation>
    </message>
    <message>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <source>none — unshadowed (DU)</source>
        <translation>keine — unverschattet (DU)</translation>
    </message>
    <message>
        <source>Bake the character to light it with shadows</source>
        <translation>Backen Sie die Figur, um sie mit Schatten zu beleuchten</translation>
    </message>
    <message>
        <source>%1
missing or unreadable — lit unshadowed (DU)</source>
        <translation>%1
fehlt oder ist nicht lesbar — unverschattet beleuchtet (DU)</translation>
    </message>
    <message>
        <source>%1
stale: it no longer fits the body or its segment tags — lit unshadowed (DU) until baked again</source>
        <translation>%1
veraltet: passt nicht mehr zum Körper oder zu seinen Segmentmarkierungen — unverschattet beleuchtet (DU), bis erneut gebacken wird</translation>
    </message>
    <message>
        <source>%1
%2, order %3, %4 rays per vertex</source>
        <translation>%1
%2, Ordnung %3, %4 Strahlen pro Vertex</translation>
    </message>
</context>
<context>
    <name>thespis::editor::BlinkProperties</name>
    <message>
        <source>Blinks</source>
        <translation>Lidschläge</translation>
    </message>
    <message>
        <source> a minute</source>
        <translation> pro Minute</translation>
    </message>
    <message>
        <source>How often the eyes blink on average: about 17 a minute at rest, 26 in conversation</source>
        <translation>Wie oft die Augen im Mittel blinzeln: etwa 17-mal pro Minute in Ruhe, 26-mal im Gespräch</translation>
    </message>
    <message>
        <source>At rest</source>
        <translation>In Ruhe</translation>
    </message>
    <message>
        <source>17 blinks a minute, as measured at rest</source>
        <translation>17 Lidschläge pro Minute, wie in Ruhe gemessen</translation>
    </message>
    <message>
        <source>Talking</source>
        <translation>Im Gespräch</translation>
    </message>
    <message>
        <source>26 blinks a minute, as measured in conversation</source>
        <translation>26 Lidschläge pro Minute, wie im Gespräch gemessen</translation>
    </message>
    <message>
        <source>Which random intervals the blinks follow: two characters with different seeds do not blink together</source>
        <translation>Welchen zufälligen Abständen die Lidschläge folgen: zwei Figuren mit verschiedenem Startwert blinzeln nicht gleichzeitig</translation>
    </message>
    <message>
        <source>A whole blink takes less than 400 ms.</source>
        <translation>Ein ganzer Lidschlag dauert weniger als 400 ms.</translation>
    </message>
    <message>
        <source>How long the lids take to close (about 100 ms). %1</source>
        <translation>Wie lange sich die Lider schließen (etwa 100 ms). %1</translation>
    </message>
    <message>
        <source>How long the eyes stay shut. %1</source>
        <translation>Wie lange die Augen geschlossen bleiben. %1</translation>
    </message>
    <message>
        <source>How long the lids take to open again (slower than closing). %1</source>
        <translation>Wie lange sich die Lider wieder öffnen (langsamer als das Schließen). %1</translation>
    </message>
    <message>
        <source>Rate:</source>
        <translation>Rate:</translation>
    </message>
    <message>
        <source>Seed:</source>
        <translation>Startwert:</translation>
    </message>
    <message>
        <source>Closing:</source>
        <translation>Schließen:</translation>
    </message>
    <message>
        <source>Shut:</source>
        <translation>Geschlossen:</translation>
    </message>
    <message>
        <source>Opening:</source>
        <translation>Öffnen:</translation>
    </message>
    <message>
        <source>Change Blink Rate</source>
        <translation>Lidschlagrate ändern</translation>
    </message>
    <message>
        <source>Change Blink Seed</source>
        <translation>Startwert der Lidschläge ändern</translation>
    </message>
    <message>
        <source>Change Blink Timing</source>
        <translation>Zeiten der Lidschläge ändern</translation>
    </message>
    <message>
        <source>Blinks (clip &quot;%1&quot;, shared by its actions)</source>
        <translation>Lidschläge (Clip „%1“, von seinen Aktionen geteilt)</translation>
    </message>
</context>
<context>
    <name>thespis::editor::BmlLexiconBox</name>
    <message>
        <source>BML lexemes</source>
        <translation>BML-Lexeme</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Hinzufügen</translation>
    </message>
    <message>
        <source>Add a lexeme playing the character&apos;s first gesture</source>
        <translation>Ein Lexem hinzufügen, das die erste Geste der Figur spielt</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <source>Remove the selected lexeme</source>
        <translation>Das ausgewählte Lexem entfernen</translation>
    </message>
    <message>
        <source>Reset to Defaults</source>
        <translation>Auf Standard zurücksetzen</translation>
    </message>
    <message>
        <source>Give the character the default lexemes again (BEAT, NOD and AGREE: agree; WAVE and GREET: greet; POINT: point)</source>
        <translation>Der Figur wieder die Standard-Lexeme geben (BEAT, NOD und AGREE: agree; WAVE und GREET: greet; POINT: point)</translation>
    </message>
    <message>
        <source>Add BML Lexeme</source>
        <translation>BML-Lexem hinzufügen</translation>
    </message>
    <message>
        <source>Remove BML Lexeme</source>
        <translation>BML-Lexem entfernen</translation>
    </message>
    <message>
        <source>Reset BML Lexemes</source>
        <translation>BML-Lexeme zurücksetzen</translation>
    </message>
    <message>
        <source>(the character&apos;s own)</source>
        <translation>(eigene der Figur)</translation>
    </message>
    <message>
        <source>(the defaults)</source>
        <translation>(Standard)</translation>
    </message>
</context>
<context>
    <name>thespis::editor::BmlLexiconModel</name>
    <message>
        <source>The character has no gesture named “%1”: BML&apos;s %2 plays no gesture through this row.</source>
        <translation>Die Figur hat keine Geste namens „%1“: BMLs %2 spielt über diese Zeile keine Geste.</translation>
    </message>
    <message>
        <source>Lexeme</source>
        <translation>Lexem</translation>
    </message>
    <message>
        <source>Gesture</source>
        <translation>Geste</translation>
    </message>
    <message>
        <source>Rename BML Lexeme</source>
        <translation>BML-Lexem umbenennen</translation>
    </message>
    <message>
        <source>Set BML Lexeme</source>
        <translation>BML-Lexem setzen</translation>
    </message>
</context>
<context>
    <name>thespis::editor::CharacterDialog</name>
    <message>
        <source>Add Character</source>
        <translation>Figur hinzufügen</translation>
    </message>
    <message>
        <source>The built-in humanoid</source>
        <translation>Der eingebaute Humanoide</translation>
    </message>
    <message>
        <source>H-Anim LOA 1 (18 joints)</source>
        <translation>H-Anim LOA 1 (18 Gelenke)</translation>
    </message>
    <message>
        <source>H-Anim, the paper&apos;s 25 joints (spine, neck, clavicles)</source>
        <translation>H-Anim, die 25 Gelenke aus dem Paper (Wirbelsäule, Hals, Schlüsselbeine)</translation>
    </message>
    <message>
        <source>H-Anim LOA 2 (71 joints, with fingers)</source>
        <translation>H-Anim LOA 2 (71 Gelenke, mit Fingern)</translation>
    </message>
    <message>
        <source>A glTF model</source>
        <translation>Ein glTF-Modell</translation>
    </message>
    <message>
        <source>No model chosen.</source>
        <translation>Kein Modell gewählt.</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>Durchsuchen…</translation>
    </message>
    <message>
        <source>Name:</source>
        <translation>Name:</translation>
    </message>
    <message>
        <source>Choose a glTF Model</source>
        <translation>glTF-Modell auswählen</translation>
    </message>
    <message>
        <source>glTF models (*.gltf *.glb)</source>
        <translation>glTF-Modelle (*.gltf *.glb)</translation>
    </message>
    <message>
        <source>%1 cannot be used: %2</source>
        <translation>%1 kann nicht verwendet werden: %2</translation>
    </message>
    <message>
        <source>Actor</source>
        <translation>Darsteller</translation>
    </message>
    <message numerus="yes">
        <source>Import its %n animation(s) as clips</source>
        <translation>
            <numerusform>%n Animation des Modells als Clip importieren</numerusform>
            <numerusform>%n Animationen des Modells als Clips importieren</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>thespis::editor::CharacterProperties</name>
    <message>
        <source>Choose Model…</source>
        <translation>Modell wählen…</translation>
    </message>
    <message>
        <source>Built-in Humanoid</source>
        <translation>Eingebauter Humanoide</translation>
    </message>
    <message>
        <source> m</source>
        <translation> m</translation>
    </message>
    <message>
        <source>Which way the character faces: 0° looks along +Z, 90° along +X</source>
        <translation>Blickrichtung der Figur: Bei 0° blickt sie entlang +Z, bei 90° entlang +X</translation>
    </message>
    <message>
        <source>Character:</source>
        <translation>Figur:</translation>
    </message>
    <message>
        <source>Body:</source>
        <translation>Körper:</translation>
    </message>
    <message>
        <source>Motion plays on:</source>
        <translation>Bewegung läuft auf:</translation>
    </message>
    <message>
        <source>Stands at:</source>
        <translation>Steht bei:</translation>
    </message>
    <message>
        <source>Faces:</source>
        <translation>Blickrichtung:</translation>
    </message>
    <message>
        <source>Has:</source>
        <translation>Enthält:</translation>
    </message>
    <message>
        <source>Rename Character</source>
        <translation>Figur umbenennen</translation>
    </message>
    <message>
        <source>Change Skeleton</source>
        <translation>Skelett ändern</translation>
    </message>
    <message>
        <source>Use the Built-in Humanoid</source>
        <translation>Eingebauten Humanoiden verwenden</translation>
    </message>
    <message>
        <source>Choose a glTF Model</source>
        <translation>glTF-Modell auswählen</translation>
    </message>
    <message>
        <source>glTF models (*.gltf *.glb)</source>
        <translation>glTF-Modelle (*.gltf *.glb)</translation>
    </message>
    <message>
        <source>Change Model</source>
        <translation>Modell ändern</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>Move Character</source>
        <translation>Figur verschieben</translation>
    </message>
    <message>
        <source>The built-in humanoid</source>
        <translation>Der eingebaute Humanoide</translation>
    </message>
    <message>
        <source>H-Anim LOA 1 (18 joints)</source>
        <translation>H-Anim LOA 1 (18 Gelenke)</translation>
    </message>
    <message>
        <source>H-Anim, the paper&apos;s 25 joints</source>
        <translation>H-Anim, die 25 Gelenke aus dem Paper</translation>
    </message>
    <message>
        <source>H-Anim LOA 2 (71 joints)</source>
        <translation>H-Anim LOA 2 (71 Gelenke)</translation>
    </message>
    <message>
        <source>The model&apos;s own rig</source>
        <translation>Das eigene Rig des Modells</translation>
    </message>
    <message>
        <source>The skeleton of clip %1</source>
        <translation>Das Skelett von Clip %1</translation>
    </message>
    <message>
        <source>%1, %2, %3</source>
        <translation>%1, %2, %3</translation>
    </message>
    <message numerus="yes">
        <source>%n layer(s)</source>
        <translation>
            <numerusform>%n Ebene</numerusform>
            <numerusform>%n Ebenen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n clip(s)</source>
        <translation>
            <numerusform>%n Clip</numerusform>
            <numerusform>%n Clips</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n action(s)</source>
        <translation>
            <numerusform>%n Aktion</numerusform>
            <numerusform>%n Aktionen</numerusform>
        </translation>
    </message>
    <message>
        <source>Choose…</source>
        <translation>Wählen…</translation>
    </message>
    <message>
        <source>Use a face mapping table file (thespis-cli face-mapping --save-mapping writes one)</source>
        <translation>Eine Gesichtszuordnungstabelle aus einer Datei verwenden (thespis-cli face-mapping --save-mapping schreibt eine)</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>Automatisch</translation>
    </message>
    <message>
        <source>Drive the face by the table recognised from the model&apos;s names</source>
        <translation>Das Gesicht mit der Tabelle steuern, die aus den Namen des Modells erkannt wird</translation>
    </message>
    <message>
        <source>Edit…</source>
        <translation>Bearbeiten…</translation>
    </message>
    <message>
        <source>Face mapping:</source>
        <translation>Gesichtszuordnung:</translation>
    </message>
    <message>
        <source>Choose a Face Mapping Table</source>
        <translation>Gesichtszuordnungstabelle wählen</translation>
    </message>
    <message>
        <source>Use the Recognised Face Mapping</source>
        <translation>Erkannte Gesichtszuordnung verwenden</translation>
    </message>
    <message>
        <source>Choose Face Mapping</source>
        <translation>Gesichtszuordnung wählen</translation>
    </message>
    <message>
        <source>Edit Face Mapping: %1</source>
        <translation>Gesichtszuordnung bearbeiten: %1</translation>
    </message>
    <message>
        <source>Save the Face Mapping Table</source>
        <translation>Gesichtszuordnungstabelle speichern</translation>
    </message>
    <message>
        <source>Edit Face Mapping</source>
        <translation>Gesichtszuordnung bearbeiten</translation>
    </message>
    <message>
        <source>Recognised from the model&apos;s names</source>
        <translation>Aus den Namen des Modells erkannt</translation>
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
        <translation>Quelle</translation>
    </message>
    <message>
        <source>keyframes in the scenario</source>
        <translation>Keyframes im Szenario</translation>
    </message>
    <message>
        <source>Drag onto a track of %1</source>
        <translation>Auf eine Spur von %1 ziehen</translation>
    </message>
    <message>
        <source>Drag a clip onto a track of its character to add an action; drop BVH or glTF files here to import them</source>
        <translation>Ziehen Sie einen Clip auf eine Spur seiner Figur, um eine Aktion hinzuzufügen; legen Sie BVH- oder glTF-Dateien hier ab, um sie zu importieren</translation>
    </message>
    <message>
        <source>idle motion from %1</source>
        <translation>Idle-Bewegung aus %1</translation>
    </message>
    <message>
        <source>Motion synthesis</source>
        <translation>Bewegungssynthese</translation>
    </message>
    <message>
        <source>Idle</source>
        <translation>Ruhebewegung</translation>
    </message>
    <message>
        <source>no idle database found</source>
        <translation>keine Ruhebewegungs-Datenbank gefunden</translation>
    </message>
    <message>
        <source>standing idle from %1</source>
        <translation>Stehen in Ruhe aus %1</translation>
    </message>
    <message>
        <source>Drag onto a body track: the character stands, shifting its weight and moving a little, for as long as the scenario plays</source>
        <translation>Auf eine Körperspur ziehen: Die Figur steht, verlagert ihr Gewicht und bewegt sich ein wenig, solange das Szenario läuft</translation>
    </message>
</context>
<context>
    <name>thespis::editor::ClipSettingsBox</name>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>thespis::editor::ContentActions</name>
    <message>
        <source>&amp;Import Motion…</source>
        <translation>Bewegung &amp;importieren…</translation>
    </message>
    <message>
        <source>Add BVH motion capture or glTF animations as clips of a character</source>
        <translation>BVH-Motion-Capture oder glTF-Animationen als Clips einer Figur hinzufügen</translation>
    </message>
    <message>
        <source>&amp;Add Character…</source>
        <translation>Figur &amp;hinzufügen…</translation>
    </message>
    <message>
        <source>Add a character on the built-in humanoid or a glTF model</source>
        <translation>Eine Figur auf dem eingebauten Humanoiden oder einem glTF-Modell hinzufügen</translation>
    </message>
    <message>
        <source>&amp;Duplicate Character</source>
        <translation>Figur &amp;duplizieren</translation>
    </message>
    <message>
        <source>A copy of the current character, a metre to its right</source>
        <translation>Eine Kopie der aktuellen Figur, einen Meter rechts von ihr</translation>
    </message>
    <message>
        <source>Re&amp;name Character…</source>
        <translation>Figur &amp;umbenennen…</translation>
    </message>
    <message>
        <source>&amp;Remove Character</source>
        <translation>Figur &amp;entfernen</translation>
    </message>
    <message>
        <source>Add &amp;Body Layer</source>
        <translation>&amp;Körperebene hinzufügen</translation>
    </message>
    <message>
        <source>A layer of body actions on top of the current character&apos;s</source>
        <translation>Eine Ebene mit Körperaktionen über denen der aktuellen Figur</translation>
    </message>
    <message>
        <source>Add &amp;Face Layer</source>
        <translation>&amp;Gesichtsebene hinzufügen</translation>
    </message>
    <message>
        <source>A layer of facial animation (MPEG-4 FAPs)</source>
        <translation>Eine Ebene mit Gesichtsanimation (MPEG-4-FAPs)</translation>
    </message>
    <message>
        <source>Rena&amp;me Layer…</source>
        <translation>Ebene u&amp;mbenennen…</translation>
    </message>
    <message>
        <source>Move Layer &amp;Up</source>
        <translation>Ebene nach &amp;oben verschieben</translation>
    </message>
    <message>
        <source>Move Layer Do&amp;wn</source>
        <translation>Ebene nach u&amp;nten verschieben</translation>
    </message>
    <message>
        <source>Remove &amp;Layer</source>
        <translation>Ebene ent&amp;fernen</translation>
    </message>
    <message>
        <source>&amp;Lighting…</source>
        <translation>Be&amp;leuchtung…</translation>
    </message>
    <message>
        <source>Choose the light probe, turn it and set its intensity</source>
        <translation>Die Lichtsonde auswählen, drehen und ihre Intensität festlegen</translation>
    </message>
    <message>
        <source>Duplicate Character</source>
        <translation>Figur duplizieren</translation>
    </message>
    <message>
        <source>Remove Character</source>
        <translation>Figur entfernen</translation>
    </message>
    <message>
        <source>Add Body Layer</source>
        <translation>Körperebene hinzufügen</translation>
    </message>
    <message>
        <source>Add Face Layer</source>
        <translation>Gesichtsebene hinzufügen</translation>
    </message>
    <message>
        <source>Move Layer Up</source>
        <translation>Ebene nach oben verschieben</translation>
    </message>
    <message>
        <source>Move Layer Down</source>
        <translation>Ebene nach unten verschieben</translation>
    </message>
    <message>
        <source>Remove Layer</source>
        <translation>Ebene entfernen</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>Import Motion</source>
        <translation>Bewegung importieren</translation>
    </message>
    <message>
        <source>Motion (*.bvh *.gltf *.glb);;BVH motion capture (*.bvh);;glTF (*.gltf *.glb);;All files (*)</source>
        <translation>Bewegung (*.bvh *.gltf *.glb);;BVH-Motion-Capture (*.bvh);;glTF (*.gltf *.glb);;Alle Dateien (*)</translation>
    </message>
    <message numerus="yes">
        <source>Import %n Clip(s)</source>
        <translation>
            <numerusform>%n Clip importieren</numerusform>
            <numerusform>%n Clips importieren</numerusform>
        </translation>
    </message>
    <message>
        <source>Imported %1 into %2.</source>
        <translation>%1 in %2 importiert.</translation>
    </message>
    <message>
        <source>Actor</source>
        <translation>Darsteller</translation>
    </message>
    <message>
        <source>Add Character</source>
        <translation>Figur hinzufügen</translation>
    </message>
    <message>
        <source>Rename Character</source>
        <translation>Figur umbenennen</translation>
    </message>
    <message>
        <source>New name:</source>
        <translation>Neuer Name:</translation>
    </message>
    <message>
        <source>Rename Layer</source>
        <translation>Ebene umbenennen</translation>
    </message>
    <message>
        <source>Change Lighting</source>
        <translation>Beleuchtung ändern</translation>
    </message>
    <message>
        <source>Add &amp;Gaze at Playhead</source>
        <translation>&amp;Blick am Abspielkopf hinzufügen</translation>
    </message>
    <message>
        <source>The current character looks at the camera (or at the other character) for two seconds from the playhead; pick what it looks at in Properties</source>
        <translation>Die aktuelle Figur blickt ab dem Abspielkopf zwei Sekunden lang in die Kamera (oder zur anderen Figur); wohin sie blickt, wählen Sie in den Eigenschaften</translation>
    </message>
    <message>
        <source>Add Gaze</source>
        <translation>Blick hinzufügen</translation>
    </message>
</context>
<context>
    <name>thespis::editor::ConversationPanel</name>
    <message>
        <source>The character the visitor talks to</source>
        <translation>Die Figur, mit der der Besucher spricht</translation>
    </message>
    <message>
        <source>Converse</source>
        <translation>Gespräch führen</translation>
    </message>
    <message>
        <source>Hand the character to the conversation from the playhead: it looks at the visitor and answers. Hand Back gives it to the scenario again; nothing it plays stops.</source>
        <translation>Die Figur ab dem Abspielkopf dem Gespräch übergeben: Sie sieht den Besucher an und antwortet. „Zurückgeben“ gibt sie wieder dem Szenario; nichts, was sie spielt, hält an.</translation>
    </message>
    <message>
        <source>Speak answers</source>
        <translation>Antworten sprechen</translation>
    </message>
    <message>
        <source>Answers are spoken with face, gestures and gaze; off, they are only written in the transcript. Chosen before Converse.</source>
        <translation>Antworten werden mit Gesicht, Gesten und Blick gesprochen; ausgeschaltet stehen sie nur im Protokoll. Vor „Gespräch führen“ zu wählen.</translation>
    </message>
    <message>
        <source>No bot loaded.</source>
        <translation>Kein Bot geladen.</translation>
    </message>
    <message>
        <source>Load Bot Folder…</source>
        <translation>Bot-Ordner laden…</translation>
    </message>
    <message>
        <source>A folder of AIML, sets, maps, substitutions and properties (Rosie’s lib/ layout or flat)</source>
        <translation>Ein Ordner mit AIML, Sets, Maps, Ersetzungen und Eigenschaften (im lib/-Aufbau von Rosie oder flach)</translation>
    </message>
    <message>
        <source>Load AIML Files…</source>
        <translation>AIML-Dateien laden…</translation>
    </message>
    <message>
        <source>One or more .aiml files (and .set, .map, … files, told by their extension)</source>
        <translation>Eine oder mehrere .aiml-Dateien (und .set-, .map-, …-Dateien, nach ihrer Endung erkannt)</translation>
    </message>
    <message>
        <source>What the bot’s files had wrong, by file:line:column; the rest loaded</source>
        <translation>Was in den Dateien des Bots falsch war, nach Datei:Zeile:Spalte; der Rest wurde geladen</translation>
    </message>
    <message>
        <source>The JSGF grammar the recogniser listens with — what the bot can answer — shows here once a bot is loaded.</source>
        <translation>Die JSGF-Grammatik, mit der die Erkennung zuhört – was der Bot beantworten kann –, erscheint hier, sobald ein Bot geladen ist.</translation>
    </message>
    <message>
        <source>Transcript</source>
        <translation>Protokoll</translation>
    </message>
    <message>
        <source>Listening Grammar</source>
        <translation>Hörgrammatik</translation>
    </message>
    <message>
        <source>What the visitor says (Return sends)</source>
        <translation>Was der Besucher sagt (Eingabetaste sendet)</translation>
    </message>
    <message>
        <source>Send</source>
        <translation>Senden</translation>
    </message>
    <message>
        <source>Hold to Talk</source>
        <translation>Gedrückt halten zum Sprechen</translation>
    </message>
    <message>
        <source>Hold while the visitor speaks into the microphone (or hold Space on the button); let go to hear it</source>
        <translation>Gedrückt halten, während der Besucher ins Mikrofon spricht (oder die Leertaste auf der Schaltfläche halten); loslassen, um es zu hören</translation>
    </message>
    <message>
        <source>Hear a Recording…</source>
        <translation>Aufnahme anhören…</translation>
    </message>
    <message>
        <source>What the visitor says, from a sound file (WAV, FLAC, OGG), recognised as the microphone would be</source>
        <translation>Was der Besucher sagt, aus einer Audiodatei (WAV, FLAC, OGG), erkannt wie vom Mikrofon</translation>
    </message>
    <message>
        <source>Save State…</source>
        <translation>Zustand speichern…</translation>
    </message>
    <message>
        <source>Keep what the visitor told the bot (its predicates, the history) in a JSON file</source>
        <translation>Was der Besucher dem Bot erzählt hat (seine Prädikate, den Verlauf), in einer JSON-Datei aufbewahren</translation>
    </message>
    <message>
        <source>Load State…</source>
        <translation>Zustand laden…</translation>
    </message>
    <message>
        <source>Converse from a saved state: the bot remembers what it was told</source>
        <translation>Von einem gespeicherten Zustand aus weitersprechen: Der Bot erinnert sich, was ihm erzählt wurde</translation>
    </message>
    <message>
        <source>No bot loaded yet</source>
        <translation>Noch kein Bot geladen</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Load Bot Folder</source>
        <translation>Bot-Ordner laden</translation>
    </message>
    <message>
        <source>Load AIML Files</source>
        <translation>AIML-Dateien laden</translation>
    </message>
    <message>
        <source>AIML files (*.aiml);;Bot files (*.aiml *.set *.map *.substitution *.properties *.pdefaults);;All files (*)</source>
        <translation>AIML-Dateien (*.aiml);;Bot-Dateien (*.aiml *.set *.map *.substitution *.properties *.pdefaults);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Hear a Recording</source>
        <translation>Aufnahme anhören</translation>
    </message>
    <message>
        <source>Sound files (*.wav *.flac *.ogg)</source>
        <translation>Audiodateien (*.wav *.flac *.ogg)</translation>
    </message>
    <message>
        <source>Save Conversation State</source>
        <translation>Gesprächszustand speichern</translation>
    </message>
    <message>
        <source>Conversation state (*.json)</source>
        <translation>Gesprächszustand (*.json)</translation>
    </message>
    <message>
        <source>Load Conversation State</source>
        <translation>Gesprächszustand laden</translation>
    </message>
    <message>
        <source>%1 left the conversation: the scenario was closed.</source>
        <translation>%1 hat das Gespräch verlassen: Das Szenario wurde geschlossen.</translation>
    </message>
    <message>
        <source>Load “%1”</source>
        <translation>„%1“ laden</translation>
    </message>
    <message>
        <source>Load the bot shipped with the demo: %1</source>
        <translation>Den mit der Demo gelieferten Bot laden: %1</translation>
    </message>
    <message>
        <source>%1 converses on, in the rebuilt scenario.</source>
        <translation>%1 spricht im neu aufgebauten Szenario weiter.</translation>
    </message>
    <message>
        <source>%1 left the conversation: the character is gone.</source>
        <translation>%1 hat das Gespräch verlassen: Die Figur gibt es nicht mehr.</translation>
    </message>
    <message>
        <source>The bot is still being prepared: wait, or cancel it first.</source>
        <translation>Der Bot wird noch vorbereitet: Warten Sie oder brechen Sie zuerst ab.</translation>
    </message>
    <message numerus="yes">
        <source>%1 and %n more</source>
        <translation>
            <numerusform>%1 und %n weitere</numerusform>
            <numerusform>%1 und %n weitere</numerusform>
        </translation>
    </message>
    <message>
        <source>Not listening</source>
        <translation>Hört nicht zu</translation>
    </message>
    <message>
        <source>Cancelled: the recogniser was not opened. Type what the visitor says.</source>
        <translation>Abgebrochen: Die Erkennung wurde nicht geöffnet. Tippen Sie, was der Besucher sagt.</translation>
    </message>
    <message numerus="yes">
        <source>%n word(s) not in the dictionary, pronounced by espeak-ng.</source>
        <translation>
            <numerusform>%n Wort nicht im Wörterbuch, von espeak-ng ausgesprochen.</numerusform>
            <numerusform>%n Wörter nicht im Wörterbuch, von espeak-ng ausgesprochen.</numerusform>
        </translation>
    </message>
    <message>
        <source>Pronounced by espeak-ng:</source>
        <translation>Von espeak-ng ausgesprochen:</translation>
    </message>
    <message>
        <source>The recogniser listens for what the bot can answer (opened in %1 s).</source>
        <translation>Die Erkennung hört auf das, was der Bot beantworten kann (geöffnet in %1 s).</translation>
    </message>
    <message>
        <source>Cancelled</source>
        <translation>Abgebrochen</translation>
    </message>
    <message>
        <source>Cancelled: the bot was not changed.</source>
        <translation>Abgebrochen: Der Bot wurde nicht geändert.</translation>
    </message>
    <message numerus="yes">
        <source>“%1”: %n categories</source>
        <translation>
            <numerusform>„%1“: %n Kategorie</numerusform>
            <numerusform>„%1“: %n Kategorien</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>, %n set(s)</source>
        <translation>
            <numerusform>, %n Set</numerusform>
            <numerusform>, %n Sets</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>, %n map(s)</source>
        <translation>
            <numerusform>, %n Map</numerusform>
            <numerusform>, %n Maps</numerusform>
        </translation>
    </message>
    <message>
        <source>Loaded in %1 s</source>
        <translation>Geladen in %1 s</translation>
    </message>
    <message numerus="yes">
        <source>%n pattern(s) to listen for</source>
        <translation>
            <numerusform>%n Muster, auf das gehört wird</numerusform>
            <numerusform>%n Muster, auf die gehört wird</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source> (%n left out)</source>
        <translation>
            <numerusform> (%n ausgelassen)</numerusform>
            <numerusform> (%n ausgelassen)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>, %n word(s); wildcards stand for %1 of them.</source>
        <translation>
            <numerusform>, %n Wort; Platzhalter stehen für %1 davon.</numerusform>
            <numerusform>, %n Wörter; Platzhalter stehen für %1 davon.</numerusform>
        </translation>
    </message>
    <message>
        <source>Nothing to listen for: %1 Type what the visitor says.</source>
        <translation>Nichts, worauf zu hören wäre: %1 Tippen Sie, was der Besucher sagt.</translation>
    </message>
    <message numerus="yes">
        <source>Loaded %n categories in %1 s.</source>
        <translation>
            <numerusform>%n Kategorie in %1 s geladen.</numerusform>
            <numerusform>%n Kategorien in %1 s geladen.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n problem(s) in its files: the rest loaded.</source>
        <translation>
            <numerusform>%n Problem in seinen Dateien: Der Rest wurde geladen.</numerusform>
            <numerusform>%n Probleme in seinen Dateien: Der Rest wurde geladen.</numerusform>
        </translation>
    </message>
    <message>
        <source>Bot loaded</source>
        <translation>Bot geladen</translation>
    </message>
    <message numerus="yes">
        <source>Bot “%1” loaded: %n categories.</source>
        <translation>
            <numerusform>Bot „%1“ geladen: %n Kategorie.</numerusform>
            <numerusform>Bot „%1“ geladen: %n Kategorien.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 converses with the new bot.</source>
        <translation>%1 spricht mit dem neuen Bot.</translation>
    </message>
    <message>
        <source>Load a bot first: it is what the character answers with.</source>
        <translation>Laden Sie zuerst einen Bot: Mit ihm antwortet die Figur.</translation>
    </message>
    <message>
        <source>Open a scenario and choose the character who converses.</source>
        <translation>Öffnen Sie ein Szenario und wählen Sie die Figur, die das Gespräch führt.</translation>
    </message>
    <message>
        <source>%1 converses with the visitor (%2).</source>
        <translation>%1 spricht mit dem Besucher (%2).</translation>
    </message>
    <message>
        <source>%1 is handed back to the scenario.</source>
        <translation>%1 ist dem Szenario zurückgegeben.</translation>
    </message>
    <message>
        <source>Answering…</source>
        <translation>Antwortet…</translation>
    </message>
    <message>
        <source>Cancelled: the character was told nothing.</source>
        <translation>Abgebrochen: Der Figur wurde nichts gesagt.</translation>
    </message>
    <message>
        <source>Heard: “%1” — confidence %2</source>
        <translation>Gehört: „%1“ – Konfidenz %2</translation>
    </message>
    <message>
        <source>Not understood — confidence %1; nothing of the grammar fits.</source>
        <translation>Nicht verstanden – Konfidenz %1; nichts aus der Grammatik passt.</translation>
    </message>
    <message>
        <source>Not understood — confidence %1; nearest: “%2”.</source>
        <translation>Nicht verstanden – Konfidenz %1; am nächsten: „%2“.</translation>
    </message>
    <message>
        <source>heard, confidence %1</source>
        <translation>gehört, Konfidenz %1</translation>
    </message>
    <message>
        <source>Typed: “%1”</source>
        <translation>Getippt: „%1“</translation>
    </message>
    <message>
        <source>typed</source>
        <translation>getippt</translation>
    </message>
    <message>
        <source>Nothing was heard: hold the button while the visitor speaks.</source>
        <translation>Nichts gehört: Halten Sie die Schaltfläche gedrückt, während der Besucher spricht.</translation>
    </message>
    <message>
        <source>Nothing to save: no character converses.</source>
        <translation>Nichts zu speichern: Keine Figur führt ein Gespräch.</translation>
    </message>
    <message>
        <source>Saved</source>
        <translation>Gespeichert</translation>
    </message>
    <message>
        <source>What the visitor told the bot is in “%1”.</source>
        <translation>Was der Besucher dem Bot erzählt hat, steht in „%1“.</translation>
    </message>
    <message>
        <source>%1 converses on from “%2”.</source>
        <translation>%1 spricht ab „%2“ weiter.</translation>
    </message>
    <message>
        <source>Loaded</source>
        <translation>Geladen</translation>
    </message>
    <message>
        <source>The conversation goes on from “%1”.</source>
        <translation>Das Gespräch geht ab „%1“ weiter.</translation>
    </message>
    <message>
        <source>Hand Back</source>
        <translation>Zurückgeben</translation>
    </message>
    <message>
        <source>Listening… %1 s — let go when the visitor is done.</source>
        <translation>Hört zu… %1 s – loslassen, wenn der Besucher fertig ist.</translation>
    </message>
    <message>
        <source>No microphone found — type what the visitor says, or use “Hear a Recording…”.</source>
        <translation>Kein Mikrofon gefunden – tippen Sie, was der Besucher sagt, oder nutzen Sie „Aufnahme anhören…“.</translation>
    </message>
    <message>
        <source>Microphone: %1. Load a bot to talk to.</source>
        <translation>Mikrofon: %1. Laden Sie einen Bot, mit dem gesprochen wird.</translation>
    </message>
    <message>
        <source>Microphone: %1. Hold to Talk works once the recogniser is open.</source>
        <translation>Mikrofon: %1. „Gedrückt halten zum Sprechen“ geht, sobald die Erkennung geöffnet ist.</translation>
    </message>
    <message>
        <source>Microphone: %1. Hold “Hold to Talk” while the visitor speaks.</source>
        <translation>Mikrofon: %1. Halten Sie „Gedrückt halten zum Sprechen“, während der Besucher spricht.</translation>
    </message>
    <message>
        <source>Ready to listen</source>
        <translation>Bereit zum Zuhören</translation>
    </message>
    <message>
        <source>the script&apos;s bot</source>
        <translation>der Bot des Skripts</translation>
    </message>
    <message>
        <source>%1 takes questions: the script handed the conversation over.</source>
        <translation>%1 beantwortet Fragen: Das Skript hat das Gespräch übergeben.</translation>
    </message>
    <message>
        <source>The recogniser listens with the same language as a graph of %1 states and %2 word arcs.</source>
        <translation>Die Spracherkennung hört dieselbe Sprache als Graph mit %1 Zuständen und %2 Wortkanten.</translation>
    </message>
</context>
<context>
    <name>thespis::editor::ConversationTranscript</name>
    <message>
        <source>Who</source>
        <translation>Wer</translation>
    </message>
    <message>
        <source>Said</source>
        <translation>Gesagt</translation>
    </message>
    <message>
        <source>Spoken (s)</source>
        <translation>Gesprochen (s)</translation>
    </message>
    <message>
        <source>Visitor</source>
        <translation>Besucher</translation>
    </message>
    <message>
        <source>(not understood)</source>
        <translation>(nicht verstanden)</translation>
    </message>
    <message>
        <source>learned</source>
        <translation>gelernt</translation>
    </message>
    <message>
        <source>not spoken</source>
        <translation>nicht gesprochen</translation>
    </message>
    <message>
        <source>(no answer: no category matched)</source>
        <translation>(keine Antwort: keine Kategorie passte)</translation>
    </message>
    <message>
        <source>Source</source>
        <translation>Quelle</translation>
    </message>
</context>
<context>
    <name>thespis::editor::CurvePanel</name>
    <message>
        <source>Weight</source>
        <translation>Gewicht</translation>
    </message>
    <message>
        <source>Scale</source>
        <translation>Skalierung</translation>
    </message>
    <message>
        <source>Constant</source>
        <translation>Konstant</translation>
    </message>
    <message>
        <source>Linear fade</source>
        <translation>Lineare Blende</translation>
    </message>
    <message>
        <source>Cubic fade</source>
        <translation>Kubische Blende</translation>
    </message>
    <message>
        <source>Linear ADSR</source>
        <translation>Lineare ADSR</translation>
    </message>
    <message>
        <source>Cubic ADSR</source>
        <translation>Kubische ADSR</translation>
    </message>
    <message>
        <source>Keyframed</source>
        <translation>Keyframes</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Edit</source>
        <translation>Bearbeiten</translation>
    </message>
    <message>
        <source>Shape</source>
        <translation>Form</translation>
    </message>
    <message>
        <source>Attack / fade in</source>
        <translation>Anstieg / Einblendung</translation>
    </message>
    <message>
        <source>Decay</source>
        <translation>Abfall</translation>
    </message>
    <message>
        <source>Sustain</source>
        <translation>Haltepegel</translation>
    </message>
    <message>
        <source>Release / fade out</source>
        <translation>Ausklingen / Ausblendung</translation>
    </message>
    <message>
        <source>Peak / value</source>
        <translation>Spitze / Wert</translation>
    </message>
    <message>
        <source>Key time</source>
        <translation>Schlüsselzeit</translation>
    </message>
    <message>
        <source>Key value</source>
        <translation>Schlüsselwert</translation>
    </message>
    <message>
        <source>Delete Curve Keys</source>
        <translation>Kurvenschlüssel löschen</translation>
    </message>
    <message>
        <source>Change Tangent</source>
        <translation>Tangente ändern</translation>
    </message>
    <message>
        <source>Set Tangent Mode</source>
        <translation>Tangentenmodus festlegen</translation>
    </message>
    <message>
        <source>Select an action on the timeline to edit its curves.</source>
        <translation>Wählen Sie eine Aktion auf der Zeitleiste aus, um ihre Kurven zu bearbeiten.</translation>
    </message>
    <message>
        <source>No action selected</source>
        <translation>Keine Aktion ausgewählt</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;%2 · %3</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;%2 · %3</translation>
    </message>
    <message>
        <source>Change Weight Curve</source>
        <translation>Gewichtskurve ändern</translation>
    </message>
    <message>
        <source>Change Scale Curve</source>
        <translation>Skalierungskurve ändern</translation>
    </message>
    <message>
        <source>Add Curve Key</source>
        <translation>Kurvenschlüssel hinzufügen</translation>
    </message>
    <message numerus="yes">
        <source>Move %n Curve Key(s)</source>
        <translation>
            <numerusform>%n Kurvenschlüssel verschieben</numerusform>
            <numerusform>%n Kurvenschlüssel verschieben</numerusform>
        </translation>
    </message>
    <message>
        <source>Set Curve Key</source>
        <translation>Kurvenschlüssel setzen</translation>
    </message>
    <message>
        <source>Dominance (coarticulation)</source>
        <translation>Dominanz (Koartikulation)</translation>
    </message>
    <message>
        <source>How sharply the dominance curve peaks (paper eq. 3): over the action, C_α(x) = e^(−α·2|x−0.5|) − 2|x−0.5|·e^(−α), 0 at both ends and the peak in the middle. A small α gives a broad hump, a large α a narrow spike.</source>
        <translation>Wie spitz die Dominanzkurve zuläuft (Gleichung 3 im Paper): über die Aktion gilt C_α(x) = e^(−α·2|x−0.5|) − 2|x−0.5|·e^(−α), 0 an beiden Enden und die Spitze in der Mitte. Ein kleines α ergibt einen breiten Buckel, ein großes α eine schmale Spitze.</translation>
    </message>
    <message>
        <source>Dominance α</source>
        <translation>Dominanz α</translation>
    </message>
</context>
<context>
    <name>thespis::editor::Document</name>
    <message>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
</context>
<context>
    <name>thespis::editor::ErrorDialog</name>
    <message>
        <source>File not found</source>
        <translation>Datei nicht gefunden</translation>
    </message>
    <message>
        <source>Not a Thespis file</source>
        <translation>Keine Thespis-Datei</translation>
    </message>
    <message>
        <source>The file is damaged</source>
        <translation>Die Datei ist beschädigt</translation>
    </message>
    <message>
        <source>Made by a newer Thespis</source>
        <translation>Mit einem neueren Thespis erstellt</translation>
    </message>
    <message>
        <source>Invalid value</source>
        <translation>Ungültiger Wert</translation>
    </message>
    <message>
        <source>The schedule cannot be built</source>
        <translation>Der Ablaufplan lässt sich nicht erstellen</translation>
    </message>
    <message>
        <source>Reading or writing failed</source>
        <translation>Lesen oder Schreiben fehlgeschlagen</translation>
    </message>
    <message>
        <source>Cancelled</source>
        <translation>Abgebrochen</translation>
    </message>
    <message>
        <source>Internal error</source>
        <translation>Interner Fehler</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <source>Not found</source>
        <translation>Nicht gefunden</translation>
    </message>
</context>
<context>
    <name>thespis::editor::ExportMotionDialog</name>
    <message>
        <source>Export Motion</source>
        <translation>Bewegung exportieren</translation>
    </message>
    <message>
        <source>A character&apos;s motion over the whole scenario, as the studio plays it, for Blender, three.js and game engines: a glTF file (.glb) with the character and its motion, or a BVH clip.</source>
        <translation>Die Bewegung einer Figur über das ganze Szenario, wie das Studio sie abspielt, für Blender, three.js und Spiel-Engines: eine glTF-Datei (.glb) mit der Figur und ihrer Bewegung oder ein BVH-Clip.</translation>
    </message>
    <message>
        <source>%1 (built-in humanoid)</source>
        <translation>%1 (eingebauter Humanoid)</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Character:</source>
        <translation>Figur:</translation>
    </message>
    <message>
        <source> fps</source>
        <translation> B/s</translation>
    </message>
    <message>
        <source>Frame rate:</source>
        <translation>Bildrate:</translation>
    </message>
    <message>
        <source>Choose…</source>
        <translation>Wählen…</translation>
    </message>
    <message>
        <source>Write to:</source>
        <translation>Schreiben nach:</translation>
    </message>
    <message>
        <source>Animation only (.glb): the joints and the motion without meshes and materials, to play onto a model already in the other tool</source>
        <translation>Nur Animation (.glb): die Gelenke und die Bewegung ohne Netze und Materialien, um sie auf ein Modell zu spielen, das schon im anderen Werkzeug ist</translation>
    </message>
    <message>
        <source>Not exported yet</source>
        <translation>Noch nicht exportiert</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exportieren</translation>
    </message>
    <message>
        <source>glTF 2.0 (*.glb);;BVH motion (*.bvh)</source>
        <translation>glTF 2.0 (*.glb);;BVH-Bewegung (*.bvh)</translation>
    </message>
    <message>
        <source>“Animation only” goes with a .glb file; a BVH file is always the motion alone.</source>
        <translation>„Nur Animation“ gilt für eine .glb-Datei; eine BVH-Datei ist immer nur die Bewegung.</translation>
    </message>
    <message>
        <source>Exported</source>
        <translation>Exportiert</translation>
    </message>
    <message numerus="yes">
        <source>Wrote %1: %n frame(s) at %2 fps.</source>
        <translation>
            <numerusform>%1 geschrieben: %n Bild bei %2 fps.</numerusform>
            <numerusform>%1 geschrieben: %n Bilder bei %2 fps.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>thespis::editor::ExportPackageDialog</name>
    <message>
        <source>Export Package</source>
        <translation>Paket exportieren</translation>
    </message>
    <message>
        <source>One file with the scenario and every file it names, which Thespis opens anywhere (File ▸ Open) and thespis-cli plays or imports.</source>
        <translation>Eine Datei mit dem Szenario und allen Dateien, die es nennt; Thespis öffnet sie überall (Datei ▸ Öffnen), thespis-cli spielt oder importiert sie.</translation>
    </message>
    <message>
        <source>In the package</source>
        <translation>Im Paket</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>Größe</translation>
    </message>
    <message>
        <source>Named by</source>
        <translation>Genannt von</translation>
    </message>
    <message>
        <source>Choose…</source>
        <translation>Wählen…</translation>
    </message>
    <message>
        <source>Write to:</source>
        <translation>Schreiben nach:</translation>
    </message>
    <message>
        <source>Not exported yet</source>
        <translation>Noch nicht exportiert</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exportieren</translation>
    </message>
    <message>
        <source>Thespis packages (*.thespkg)</source>
        <translation>Thespis-Pakete (*.thespkg)</translation>
    </message>
    <message>
        <source>the scenario itself, with its scripts and gestures</source>
        <translation>das Szenario selbst, mit seinen Skripten und Gesten</translation>
    </message>
    <message numerus="yes">
        <source>The scenario and %n file(s), %1 before compression.</source>
        <translation>
            <numerusform>Das Szenario und %n Datei, %1 vor der Kompression.</numerusform>
            <numerusform>Das Szenario und %n Dateien, %1 vor der Kompression.</numerusform>
        </translation>
    </message>
    <message>
        <source>Exported</source>
        <translation>Exportiert</translation>
    </message>
    <message>
        <source>Wrote %1: %2 (%3 before compression).</source>
        <translation>%1 geschrieben: %2 (%3 vor der Kompression).</translation>
    </message>
    <message>
        <source>Bake the lighting first where a character has no bake or an out-of-date one (the new bakes go into the package only)</source>
        <translation>Zuerst die Beleuchtung backen, wo eine Figur keine oder eine veraltete Bake hat (die neuen Bakes kommen nur ins Paket)</translation>
    </message>
    <message>
        <source>Baked the lighting of %1.</source>
        <translation>Beleuchtung von %1 gebacken.</translation>
    </message>
</context>
<context>
    <name>thespis::editor::FaceMappingDialog</name>
    <message>
        <source>Face mapping tables (*.json);;All files (*)</source>
        <translation>Gesichtszuordnungstabellen (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Face Mapping of %1</source>
        <translation>Gesichtszuordnung von %1</translation>
    </message>
    <message>
        <source>Each row drives one of the model&apos;s morph targets by a face channel: the target&apos;s weight is the channel&apos;s value times the coefficient (of its positive or negative part only, when one side is chosen).</source>
        <translation>Jede Zeile steuert eines der Morph-Ziele des Modells über einen Gesichtskanal: Das Gewicht des Ziels ist der Wert des Kanals mal dem Koeffizienten (nur sein positiver oder negativer Anteil, wenn eine Seite gewählt ist).</translation>
    </message>
    <message>
        <source>Morph target</source>
        <translation>Morph-Ziel</translation>
    </message>
    <message>
        <source>Channel</source>
        <translation>Kanal</translation>
    </message>
    <message>
        <source>Coefficient</source>
        <translation>Koeffizient</translation>
    </message>
    <message>
        <source>Side</source>
        <translation>Seite</translation>
    </message>
    <message>
        <source>Joint</source>
        <translation>Gelenk</translation>
    </message>
    <message>
        <source>Axis (x, y, z)</source>
        <translation>Achse (x, y, z)</translation>
    </message>
    <message>
        <source>Radians per unit</source>
        <translation>Radiant pro Einheit</translation>
    </message>
    <message>
        <source>Add Drive</source>
        <translation>Ansteuerung hinzufügen</translation>
    </message>
    <message>
        <source>Remove Drive</source>
        <translation>Ansteuerung entfernen</translation>
    </message>
    <message>
        <source>Add Joint Drive</source>
        <translation>Gelenkansteuerung hinzufügen</translation>
    </message>
    <message>
        <source>Remove Joint Drive</source>
        <translation>Gelenkansteuerung entfernen</translation>
    </message>
    <message>
        <source>Load…</source>
        <translation>Laden…</translation>
    </message>
    <message>
        <source>Save As…</source>
        <translation>Speichern unter…</translation>
    </message>
    <message>
        <source>Recognise from Model</source>
        <translation>Aus dem Modell erkennen</translation>
    </message>
    <message>
        <source>The table the model&apos;s names give: ARKit blendshapes, Oculus visemes, expression targets, eye and jaw bones</source>
        <translation>Die Tabelle, die sich aus den Namen des Modells ergibt: ARKit-Blendshapes, Oculus-Viseme, Ausdrucksziele, Augen- und Kieferknochen</translation>
    </message>
    <message>
        <source>Morph targets:</source>
        <translation>Morph-Ziele:</translation>
    </message>
    <message>
        <source>Joints:</source>
        <translation>Gelenke:</translation>
    </message>
    <message>
        <source>Load a Face Mapping Table</source>
        <translation>Gesichtszuordnungstabelle laden</translation>
    </message>
    <message>
        <source>Save the Face Mapping Table</source>
        <translation>Gesichtszuordnungstabelle speichern</translation>
    </message>
    <message>
        <source>Both</source>
        <translation>Beide</translation>
    </message>
    <message>
        <source>Positive values only</source>
        <translation>Nur positive Werte</translation>
    </message>
    <message>
        <source>Negative values only</source>
        <translation>Nur negative Werte</translation>
    </message>
    <message>
        <source>%1 has no morph target %2: those rows move nothing.</source>
        <translation>%1 hat kein Morph-Ziel %2: Diese Zeilen bewegen nichts.</translation>
    </message>
    <message>
        <source>%1 has no joint %2: those rows turn nothing.</source>
        <translation>%1 hat kein Gelenk %2: Diese Zeilen drehen nichts.</translation>
    </message>
    <message>
        <source>Every morph target and joint the table names is in %1.</source>
        <translation>Jedes Morph-Ziel und Gelenk, das die Tabelle nennt, ist in %1 vorhanden.</translation>
    </message>
    <message>
        <source>Could not load the face mapping table.</source>
        <translation>Die Gesichtszuordnungstabelle konnte nicht geladen werden.</translation>
    </message>
    <message>
        <source>Could not save the face mapping table.</source>
        <translation>Die Gesichtszuordnungstabelle konnte nicht gespeichert werden.</translation>
    </message>
</context>
<context>
    <name>thespis::editor::FacePosePanel</name>
    <message>
        <source>Whose face to pose</source>
        <translation>Wessen Gesicht gestellt wird</translation>
    </message>
    <message>
        <source>Pose</source>
        <translation>Stellen</translation>
    </message>
    <message>
        <source>Show the pose on the character&apos;s face in the 3D view (close up), over what the face plays; the document does not change</source>
        <translation>Die Pose im Gesicht der Figur in der 3D-Ansicht zeigen (Nahaufnahme), über dem, was das Gesicht spielt; das Dokument ändert sich nicht</translation>
    </message>
    <message>
        <source>From Playhead</source>
        <translation>Vom Abspielkopf</translation>
    </message>
    <message>
        <source>Start from the character&apos;s face as it is at the playhead</source>
        <translation>Vom Gesicht der Figur ausgehen, wie es am Abspielkopf ist</translation>
    </message>
    <message>
        <source>Neutral</source>
        <translation>Neutral</translation>
    </message>
    <message>
        <source>Every slider back to 0: the neutral face</source>
        <translation>Alle Regler zurück auf 0: das neutrale Gesicht</translation>
    </message>
    <message>
        <source>Expressions</source>
        <translation>Ausdrücke</translation>
    </message>
    <message>
        <source>Mouth and jaw</source>
        <translation>Mund und Kiefer</translation>
    </message>
    <message>
        <source>Eyes and lids</source>
        <translation>Augen und Lider</translation>
    </message>
    <message>
        <source>Brows</source>
        <translation>Brauen</translation>
    </message>
    <message>
        <source>Cheeks</source>
        <translation>Wangen</translation>
    </message>
    <message>
        <source>Tongue</source>
        <translation>Zunge</translation>
    </message>
    <message>
        <source>Head</source>
        <translation>Kopf</translation>
    </message>
    <message>
        <source>Nose and ears</source>
        <translation>Nase und Ohren</translation>
    </message>
    <message>
        <source>Visemes</source>
        <translation>Viseme</translation>
    </message>
    <message>
        <source>face pose</source>
        <translation>Gesichtspose</translation>
    </message>
    <message>
        <source>The name of the face clip (and gesture) to save</source>
        <translation>Der Name des zu speichernden Gesichtsclips (und der Geste)</translation>
    </message>
    <message>
        <source>Gesture too</source>
        <translation>Auch als Geste</translation>
    </message>
    <message>
        <source>Also add a gesture of that name to the character&apos;s gesticon, for scripts and speech to play</source>
        <translation>Auch eine Geste dieses Namens zum Gestikon der Figur hinzufügen, die Skripte und Sprache abspielen können</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Speichern</translation>
    </message>
    <message>
        <source>Add the pose to the character as a face clip (one undoable step)</source>
        <translation>Die Pose der Figur als Gesichtsclip hinzufügen (ein rückgängig machbarer Schritt)</translation>
    </message>
    <message>
        <source>Name:</source>
        <translation>Name:</translation>
    </message>
    <message>
        <source>FAP %1, in %2 units; positive: %3</source>
        <translation>FAP %1, in %2-Einheiten; positiv: %3</translation>
    </message>
    <message>
        <source>viseme %1</source>
        <translation>Visem %1</translation>
    </message>
    <message>
        <source>Weight of MPEG-4 viseme %1, in percent</source>
        <translation>Gewicht des MPEG-4-Visems %1, in Prozent</translation>
    </message>
    <message>
        <source>Intensity of the expression, in percent</source>
        <translation>Stärke des Ausdrucks, in Prozent</translation>
    </message>
    <message>
        <source>Cannot show the pose: %1</source>
        <translation>Die Pose kann nicht gezeigt werden: %1</translation>
    </message>
    <message>
        <source>Give the face clip a name.</source>
        <translation>Geben Sie dem Gesichtsclip einen Namen.</translation>
    </message>
    <message>
        <source>Open a scenario with a character first.</source>
        <translation>Öffnen Sie zuerst ein Szenario mit einer Figur.</translation>
    </message>
    <message>
        <source>The face is neutral: move a slider first.</source>
        <translation>Das Gesicht ist neutral: bewegen Sie zuerst einen Regler.</translation>
    </message>
    <message>
        <source>Save Face Pose as Clip and Gesture</source>
        <translation>Gesichtspose als Clip und Geste speichern</translation>
    </message>
    <message>
        <source>Save Face Pose</source>
        <translation>Gesichtspose speichern</translation>
    </message>
    <message>
        <source>Saved face clip &quot;%1&quot;%2.</source>
        <translation>Gesichtsclip „%1“%2 gespeichert.</translation>
    </message>
    <message>
        <source> and gesture</source>
        <translation> und Geste</translation>
    </message>
</context>
<context>
    <name>thespis::editor::GazeProperties</name>
    <message>
        <source>Looks at</source>
        <translation>Blickt auf</translation>
    </message>
    <message>
        <source>The eyes alone</source>
        <translation>Nur die Augen</translation>
    </message>
    <message>
        <source>Eyes and head</source>
        <translation>Augen und Kopf</translation>
    </message>
    <message>
        <source>Eyes, head and shoulders</source>
        <translation>Augen, Kopf und Schultern</translation>
    </message>
    <message>
        <source>Eyes, head, shoulders and waist</source>
        <translation>Augen, Kopf, Schultern und Hüfte</translation>
    </message>
    <message>
        <source>°</source>
        <translation>°</translation>
    </message>
    <message>
        <source>right</source>
        <translation>rechts</translation>
    </message>
    <message>
        <source>left</source>
        <translation>links</translation>
    </message>
    <message>
        <source>up</source>
        <translation>oben</translation>
    </message>
    <message>
        <source>down</source>
        <translation>unten</translation>
    </message>
    <message>
        <source>up and right</source>
        <translation>rechts oben</translation>
    </message>
    <message>
        <source>up and left</source>
        <translation>links oben</translation>
    </message>
    <message>
        <source>down and right</source>
        <translation>rechts unten</translation>
    </message>
    <message>
        <source>down and left</source>
        <translation>links unten</translation>
    </message>
    <message>
        <source>Target:</source>
        <translation>Ziel:</translation>
    </message>
    <message>
        <source>Turns:</source>
        <translation>Dreht:</translation>
    </message>
    <message>
        <source>Away by:</source>
        <translation>Daneben um:</translation>
    </message>
    <message>
        <source>Toward:</source>
        <translation>Richtung:</translation>
    </message>
</context>
<context>
    <name>thespis::editor::GesticonModel</name>
    <message>
        <source>The dependent-joint filter runs over this gesture: spine and neck follow it</source>
        <translation>Der Filter für abhängige Gelenke wird auf diese Geste angewendet: Wirbelsäule und Hals folgen ihr</translation>
    </message>
    <message>
        <source>Only the joints of the gesture&apos;s clip move</source>
        <translation>Nur die Gelenke des Clips der Geste bewegen sich</translation>
    </message>
    <message>
        <source>The gesture drives every joint its clip has</source>
        <translation>Die Geste steuert jedes Gelenk ihres Clips</translation>
    </message>
    <message>
        <source>Whole body</source>
        <translation>Ganzer Körper</translation>
    </message>
    <message>
        <source>The gesture drives the joints of mask &quot;%1&quot;</source>
        <translation>Die Geste steuert die Gelenke der Maske „%1“</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Clip</source>
        <translation>Clip</translation>
    </message>
    <message>
        <source>Body part</source>
        <translation>Körperteil</translation>
    </message>
    <message>
        <source>Fade in (s)</source>
        <translation>Einblenden (s)</translation>
    </message>
    <message>
        <source>Fade out (s)</source>
        <translation>Ausblenden (s)</translation>
    </message>
    <message>
        <source>Dependent joints</source>
        <translation>Abhängige Gelenke</translation>
    </message>
    <message>
        <source>The name speech scripts use to trigger the gesture</source>
        <translation>Der Name, mit dem Sprachskripte die Geste auslösen</translation>
    </message>
    <message>
        <source>The character&apos;s clip the gesture plays</source>
        <translation>Der Clip der Figur, den die Geste abspielt</translation>
    </message>
    <message>
        <source>The joint mask that limits the gesture to a body part</source>
        <translation>Die Gelenkmaske, die die Geste auf einen Körperteil beschränkt</translation>
    </message>
    <message>
        <source>How long the gesture takes to blend in, in seconds</source>
        <translation>Wie lange das Einblenden der Geste dauert, in Sekunden</translation>
    </message>
    <message>
        <source>How long the gesture takes to blend out, in seconds</source>
        <translation>Wie lange das Ausblenden der Geste dauert, in Sekunden</translation>
    </message>
    <message>
        <source>Dependent-joint filter: joints the gesture does not drive (spine, neck) follow it</source>
        <translation>Filter für abhängige Gelenke: Gelenke, die die Geste nicht steuert (Wirbelsäule, Hals), folgen ihr</translation>
    </message>
    <message>
        <source>Turn Dependent-Joint Filter On</source>
        <translation>Filter für abhängige Gelenke einschalten</translation>
    </message>
    <message>
        <source>Turn Dependent-Joint Filter Off</source>
        <translation>Filter für abhängige Gelenke ausschalten</translation>
    </message>
    <message>
        <source>Rename Gesture</source>
        <translation>Geste umbenennen</translation>
    </message>
    <message>
        <source>Change Gesture Clip</source>
        <translation>Clip der Geste ändern</translation>
    </message>
    <message>
        <source>Change Gesture Body Part</source>
        <translation>Körperteil der Geste ändern</translation>
    </message>
    <message>
        <source>A fade time must be a number of seconds.</source>
        <translation>Eine Blendzeit muss eine Anzahl von Sekunden sein.</translation>
    </message>
    <message>
        <source>Change Gesture Fade In</source>
        <translation>Einblendung der Geste ändern</translation>
    </message>
    <message>
        <source>Change Gesture Fade Out</source>
        <translation>Ausblendung der Geste ändern</translation>
    </message>
    <message>
        <source>The filter keeps upper-body PCs 1–%1, fades them out to PC %2 and mutes the rest: a later start keeps the gesture closer to its keys</source>
        <translation>Der Filter behält die Oberkörper-HK 1–%1, blendet sie bis HK %2 aus und schaltet den Rest stumm: ein späterer Beginn hält die Geste näher an ihren Keys</translation>
    </message>
    <message>
        <source>Filter PCs</source>
        <translation>Filter-HK</translation>
    </message>
    <message>
        <source>The filter&apos;s band, e.g. 20–30: PCs kept up to the first, muted above the second (paper: 20–30 of 48)</source>
        <translation>Das Band des Filters, z. B. 20–30: HK bis zur ersten behalten, über der zweiten stumm (Artikel: 20–30 von 48)</translation>
    </message>
    <message>
        <source>Write the filter&apos;s band as two PC numbers, e.g. 30–40.</source>
        <translation>Das Band des Filters als zwei HK-Nummern schreiben, z. B. 30–40.</translation>
    </message>
    <message>
        <source>Change Filter Band</source>
        <translation>Filterband ändern</translation>
    </message>
    <message>
        <source>Speech plays it at its own speed and holds its stroke while the words last</source>
        <translation>Die Sprache spielt sie in ihrem eigenen Tempo und hält ihren Schlag, solange die Wörter dauern</translation>
    </message>
    <message>
        <source>Speech stretches or shrinks it to its words</source>
        <translation>Die Sprache dehnt oder staucht sie auf ihre Wörter</translation>
    </message>
    <message>
        <source>No stroke marked: speech fits the gesture as a whole</source>
        <translation>Kein Schlag markiert: Die Sprache passt die Geste als Ganzes ein</translation>
    </message>
    <message>
        <source>The stroke, %1 s into the clip, falls on the first stressed word of its words</source>
        <translation>Der Schlag, %1 s im Clip, fällt auf das erste betonte ihrer Wörter</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>Holds</source>
        <translation>Hält</translation>
    </message>
    <message>
        <source>Stroke (s)</source>
        <translation>Schlag (s)</translation>
    </message>
    <message>
        <source>Words longer than the gesture: hold its stroke (checked) or stretch it (unchecked)</source>
        <translation>Wörter länger als die Geste: ihren Schlag halten (angekreuzt) oder sie dehnen (nicht angekreuzt)</translation>
    </message>
    <message>
        <source>Where the gesture&apos;s stroke is in its clip, in seconds: speech puts it on the stressed word</source>
        <translation>Wo der Schlag der Geste in ihrem Clip liegt, in Sekunden: Die Sprache legt ihn auf das betonte Wort</translation>
    </message>
    <message>
        <source>Hold Gesture Stroke</source>
        <translation>Schlag der Geste halten</translation>
    </message>
    <message>
        <source>Stretch Gesture to Its Words</source>
        <translation>Geste auf ihre Wörter dehnen</translation>
    </message>
    <message>
        <source>A stroke is a number of seconds into the clip (below 0: none).</source>
        <translation>Ein Schlag ist eine Anzahl Sekunden im Clip (unter 0: keiner).</translation>
    </message>
    <message>
        <source>Mark Gesture Stroke</source>
        <translation>Schlag der Geste markieren</translation>
    </message>
</context>
<context>
    <name>thespis::editor::GesticonPanel</name>
    <message>
        <source>The character whose gesture database is shown</source>
        <translation>Die Figur, deren Gestendatenbank angezeigt wird</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Hinzufügen</translation>
    </message>
    <message>
        <source>Add a gesture playing the character&apos;s first clip</source>
        <translation>Eine Geste hinzufügen, die den ersten Clip der Figur abspielt</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <source>Remove the selected gestures</source>
        <translation>Die ausgewählten Gesten entfernen</translation>
    </message>
    <message>
        <source>Rename</source>
        <translation>Umbenennen</translation>
    </message>
    <message>
        <source>Rename the selected gesture</source>
        <translation>Die ausgewählte Geste umbenennen</translation>
    </message>
    <message>
        <source>Preview</source>
        <translation>Vorschau</translation>
    </message>
    <message>
        <source>The character has no clips to make a gesture from</source>
        <translation>Die Figur hat keine Clips, aus denen sich eine Geste erstellen ließe</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <source>Stop the preview and show the document again</source>
        <translation>Die Vorschau beenden und wieder das Dokument anzeigen</translation>
    </message>
    <message>
        <source>Character &quot;%1&quot; has no clips to make a gesture from.</source>
        <translation>Die Figur „%1“ hat keine Clips, aus denen sich eine Geste erstellen ließe.</translation>
    </message>
    <message>
        <source>gesture</source>
        <translation>Geste</translation>
    </message>
    <message>
        <source>Add Gesture</source>
        <translation>Geste hinzufügen</translation>
    </message>
    <message numerus="yes">
        <source>Remove %n Gesture(s)</source>
        <translation>
            <numerusform>%n Geste entfernen</numerusform>
            <numerusform>%n Gesten entfernen</numerusform>
        </translation>
    </message>
    <message>
        <source>Cannot preview gesture &quot;%1&quot;: %2</source>
        <translation>Vorschau der Geste „%1“ nicht möglich: %2</translation>
    </message>
    <message>
        <source>Cannot preview gesture &quot;%1&quot;: its clip has no finite length.</source>
        <translation>Vorschau der Geste „%1“ nicht möglich: Ihr Clip hat keine endliche Länge.</translation>
    </message>
    <message>
        <source>Before / After</source>
        <translation>Vorher / Nachher</translation>
    </message>
    <message>
        <source>Play the selected gesture twice from the playhead: without the dependent-joint filter, then with it (spine and neck follow the gesture)</source>
        <translation>Die ausgewählte Geste zweimal ab der Abspielposition spielen: ohne den Filter für abhängige Gelenke, dann mit ihm (Wirbelsäule und Hals folgen der Geste)</translation>
    </message>
    <message>
        <source>Before: &quot;%1&quot; without the dependent-joint filter</source>
        <translation>Vorher: &quot;%1&quot; ohne den Filter für abhängige Gelenke</translation>
    </message>
    <message>
        <source>After: &quot;%1&quot; with the dependent-joint filter (spine and neck follow)</source>
        <translation>Nachher: &quot;%1&quot; mit dem Filter für abhängige Gelenke (Wirbelsäule und Hals folgen)</translation>
    </message>
    <message>
        <source>Open a scenario to preview its gestures</source>
        <translation>Öffnen Sie ein Szenario, um seine Gesten vorzuschauen</translation>
    </message>
    <message>
        <source>Play the selected gesture on the character from the playhead, over what it plays, as a script would (the document does not change)</source>
        <translation>Spielt die gewählte Geste ab dem Abspielkopf auf der Figur, über dem, was sie spielt, wie ein Skript es täte (das Dokument ändert sich nicht)</translation>
    </message>
    <message>
        <source>Cannot preview gesture &quot;%1&quot;: it cannot be played (Messages says why).</source>
        <translation>Geste „%1“ kann nicht vorgeschaut werden: Sie kann nicht gespielt werden (Meldungen sagt, warum).</translation>
    </message>
    <message>
        <source>Cannot preview gesture &quot;%1&quot; with the dependent-joint filter: the scenario names no posture bases (a .pca file made by thespis-cli train-pca).</source>
        <translation>Geste „%1“ kann nicht mit dem Filter für abhängige Gelenke vorgeschaut werden: Das Szenario nennt keine Haltungsbasen (eine .pca-Datei von thespis-cli train-pca).</translation>
    </message>
</context>
<context>
    <name>thespis::editor::IdleProperties</name>
    <message>
        <source>Idle motion</source>
        <translation>Ruhebewegung</translation>
    </message>
    <message>
        <source>Choose…</source>
        <translation>Wählen…</translation>
    </message>
    <message>
        <source>Play another idle motion database (.idle, made by thespis-cli build-idle)</source>
        <translation>Eine andere Ruhebewegungs-Datenbank abspielen (.idle, erzeugt mit thespis-cli build-idle)</translation>
    </message>
    <message>
        <source>Which motion program the character follows: characters with different seeds shift their weight at different times</source>
        <translation>Welchem Bewegungsprogramm die Figur folgt: Figuren mit verschiedenen Startwerten verlagern ihr Gewicht zu verschiedenen Zeiten</translation>
    </message>
    <message>
        <source>Size of the small posture variations: 0 none, 1 as much as in the recordings</source>
        <translation>Größe der kleinen Haltungsschwankungen: 0 keine, 1 so viel wie in den Aufnahmen</translation>
    </message>
    <message>
        <source>Database:</source>
        <translation>Datenbank:</translation>
    </message>
    <message>
        <source>Seed:</source>
        <translation>Startwert:</translation>
    </message>
    <message>
        <source>Variations:</source>
        <translation>Schwankungen:</translation>
    </message>
    <message>
        <source>Change Idle Seed</source>
        <translation>Startwert der Ruhebewegung ändern</translation>
    </message>
    <message>
        <source>Change Idle Variations</source>
        <translation>Schwankungen der Ruhebewegung ändern</translation>
    </message>
    <message>
        <source>Choose an Idle Motion Database</source>
        <translation>Ruhebewegungs-Datenbank wählen</translation>
    </message>
    <message>
        <source>Idle motion databases (*.idle)</source>
        <translation>Ruhebewegungs-Datenbanken (*.idle)</translation>
    </message>
    <message>
        <source>Idle motion (clip &quot;%1&quot;, shared by its actions)</source>
        <translation>Ruhebewegung (Clip &quot;%1&quot;, von seinen Aktionen geteilt)</translation>
    </message>
    <message>
        <source>Change Idle Database</source>
        <translation>Ruhebewegungs-Datenbank ändern</translation>
    </message>
</context>
<context>
    <name>thespis::editor::ImportMotionDialog</name>
    <message>
        <source>CMU (MotionBuilder names)</source>
        <translation>CMU (MotionBuilder-Namen)</translation>
    </message>
    <message>
        <source>CMU (3ds Max names)</source>
        <translation>CMU (3ds-Max-Namen)</translation>
    </message>
    <message>
        <source>your mapping</source>
        <translation>Ihre Zuordnung</translation>
    </message>
    <message>
        <source>none recognised</source>
        <translation>keine erkannt</translation>
    </message>
    <message>
        <source>found from the rig</source>
        <translation>aus dem Rig ermittelt</translation>
    </message>
    <message>
        <source>Import Motion</source>
        <translation>Bewegung importieren</translation>
    </message>
    <message>
        <source>File and clips</source>
        <translation>Datei und Clips</translation>
    </message>
    <message>
        <source>What was found</source>
        <translation>Gefundener Inhalt</translation>
    </message>
    <message>
        <source>Joint in the file</source>
        <translation>Gelenk in der Datei</translation>
    </message>
    <message>
        <source>Plays as (H-Anim name)</source>
        <translation>Spielt als (H-Anim-Name)</translation>
    </message>
    <message>
        <source>Type the H-Anim joint a file joint should drive (l_hip, vl5, skullbase …); leave it empty, or the file&apos;s own name, to leave the joint out. Then Apply Mapping.</source>
        <translation>Geben Sie das H-Anim-Gelenk ein, das ein Gelenk der Datei steuern soll (l_hip, vl5, skullbase …); lassen Sie das Feld leer oder den Namen aus der Datei stehen, um das Gelenk auszulassen. Dann „Zuordnung anwenden“.</translation>
    </message>
    <message>
        <source>Apply Mapping</source>
        <translation>Zuordnung anwenden</translation>
    </message>
    <message>
        <source>Load Mapping…</source>
        <translation>Zuordnung laden…</translation>
    </message>
    <message>
        <source>Save Mapping…</source>
        <translation>Zuordnung speichern…</translation>
    </message>
    <message>
        <source>Import</source>
        <translation>Importieren</translation>
    </message>
    <message>
        <source>Import into:</source>
        <translation>Importieren in:</translation>
    </message>
    <message>
        <source>Load Joint Mapping</source>
        <translation>Gelenkzuordnung laden</translation>
    </message>
    <message>
        <source>Joint mappings (*.map *.txt);;All files (*)</source>
        <translation>Gelenkzuordnungen (*.map *.txt);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Save Joint Mapping</source>
        <translation>Gelenkzuordnung speichern</translation>
    </message>
    <message>
        <source>Joint mappings (*.map)</source>
        <translation>Gelenkzuordnungen (*.map)</translation>
    </message>
    <message>
        <source>There is no character to import into: add one first (Character ▸ Add Character…).</source>
        <translation>Es gibt keine Figur, in die importiert werden kann: Fügen Sie zuerst eine hinzu (Figur ▸ Figur hinzufügen…).</translation>
    </message>
    <message>
        <source>cannot be read</source>
        <translation>nicht lesbar</translation>
    </message>
    <message>
        <source>moves none of the character&apos;s joints</source>
        <translation>bewegt keines der Gelenke der Figur</translation>
    </message>
    <message numerus="yes">
        <source>%1, %n frame(s) at %2 fps</source>
        <translation>
            <numerusform>%1, %n Bild bei %2 B/s</numerusform>
            <numerusform>%1, %n Bilder bei %2 B/s</numerusform>
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
        <translation>Animation</translation>
    </message>
    <message>
        <source>No files to import.</source>
        <translation>Keine Dateien zum Importieren.</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1 cannot be read&lt;/b&gt;: %2&lt;br&gt;Nothing of it is imported.</source>
        <translation>&lt;b&gt;%1 ist nicht lesbar&lt;/b&gt;: %2&lt;br&gt;Nichts daraus wird importiert.</translation>
    </message>
    <message numerus="yes">
        <source>&lt;b&gt;%1&lt;/b&gt;: %2, %n frame(s) at %3 fps.</source>
        <translation>
            <numerusform>&lt;b&gt;%1&lt;/b&gt;: %2, %n Bild bei %3 B/s.</numerusform>
            <numerusform>&lt;b&gt;%1&lt;/b&gt;: %2, %n Bilder bei %3 B/s.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Joint names: %1; it moves %n of the character&apos;s joints.</source>
        <translation>
            <numerusform>Gelenknamen: %1; die Datei bewegt %n Gelenk der Figur.</numerusform>
            <numerusform>Gelenknamen: %1; die Datei bewegt %n Gelenke der Figur.</numerusform>
        </translation>
    </message>
    <message>
        <source>Unit: %1. The motion is resized to the character by the length of the legs.</source>
        <translation>Einheit: %1. Die Bewegung wird anhand der Beinlänge an die Größe der Figur angepasst.</translation>
    </message>
    <message>
        <source>The body lay %1 in the file: it is stood up (+Y up, facing +Z).</source>
        <translation>In der Datei lag der Körper anders (%1): Er wird aufgerichtet (+Y nach oben, Blick nach +Z).</translation>
    </message>
    <message>
        <source>Its first frame is a calibration pose (a T-pose): it is left out.</source>
        <translation>Das erste Bild ist eine Kalibrierpose (eine T-Pose): Es wird ausgelassen.</translation>
    </message>
    <message numerus="yes">
        <source>%n more</source>
        <translation>
            <numerusform>%n weiteres</numerusform>
            <numerusform>%n weitere</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Joint mapping of %1 (%n joint(s)):</source>
        <translation>
            <numerusform>Gelenkzuordnung von %1 (%n Gelenk):</numerusform>
            <numerusform>Gelenkzuordnung von %1 (%n Gelenke):</numerusform>
        </translation>
    </message>
    <message>
        <source>&lt;b&gt;The mapping file cannot be read&lt;/b&gt;: %1</source>
        <translation>&lt;b&gt;Die Zuordnungsdatei ist nicht lesbar&lt;/b&gt;: %1</translation>
    </message>
    <message numerus="yes">
        <source>Import %n Clip(s)</source>
        <translation>
            <numerusform>%n Clip importieren</numerusform>
            <numerusform>%n Clips importieren</numerusform>
        </translation>
    </message>
    <message>
        <source>The character&apos;s joints it leaves at rest: %1.</source>
        <translation>Gelenke der Figur, die in Ruhe bleiben: %1.</translation>
    </message>
    <message numerus="yes">
        <source>%n joint(s) have no H-Anim name and keep their own: %1.</source>
        <translation>
            <numerusform>%n Gelenk hat keinen H-Anim-Namen und behält seinen eigenen: %1.</numerusform>
            <numerusform>%n Gelenke haben keinen H-Anim-Namen und behalten ihren eigenen: %1.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Of these, %n move(s) nothing of this character (neither they nor a joint below them is in its skeleton): %1.</source>
        <translation>
            <numerusform>Davon bewegt %n nichts an dieser Figur (weder es noch ein Gelenk darunter ist in ihrem Skelett): %1.</numerusform>
            <numerusform>Davon bewegen %n nichts an dieser Figur (weder sie noch ein Gelenk darunter sind in ihrem Skelett): %1.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>thespis::editor::JobProgress</name>
    <message>
        <source>Starting…</source>
        <translation>Starte…</translation>
    </message>
    <message>
        <source>%1 — %p%</source>
        <translation>%1 — %p%</translation>
    </message>
    <message>
        <source>Cancelled</source>
        <translation>Abgebrochen</translation>
    </message>
    <message>
        <source>Failed</source>
        <translation>Fehlgeschlagen</translation>
    </message>
    <message>
        <source>Cancelled: nothing was written.</source>
        <translation>Abgebrochen: nichts wurde geschrieben.</translation>
    </message>
</context>
<context>
    <name>thespis::editor::JointMaskPanel</name>
    <message>
        <source>The mask to edit; actions that name it all change with it</source>
        <translation>Die zu bearbeitende Maske; alle Aktionen, die sie verwenden, ändern sich mit</translation>
    </message>
    <message>
        <source>Rename…</source>
        <translation>Umbenennen…</translation>
    </message>
    <message>
        <source>Rename the mask and every action and gesture using it</source>
        <translation>Die Maske umbenennen, auch in jeder Aktion und Geste, die sie verwendet</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Löschen</translation>
    </message>
    <message>
        <source>Delete the mask (only when nothing uses it)</source>
        <translation>Die Maske löschen (nur wenn nichts sie verwendet)</translation>
    </message>
    <message>
        <source>Presets</source>
        <translation>Vorgaben</translation>
    </message>
    <message>
        <source>Replace the weights by a preset</source>
        <translation>Die Gewichte durch eine Vorgabe ersetzen</translation>
    </message>
    <message>
        <source>Full Body</source>
        <translation>Ganzer Körper</translation>
    </message>
    <message>
        <source>Upper Body</source>
        <translation>Oberkörper</translation>
    </message>
    <message>
        <source>Lower Body</source>
        <translation>Unterkörper</translation>
    </message>
    <message>
        <source>Left Arm</source>
        <translation>Linker Arm</translation>
    </message>
    <message>
        <source>Right Arm</source>
        <translation>Rechter Arm</translation>
    </message>
    <message>
        <source>Head and Neck</source>
        <translation>Kopf und Hals</translation>
    </message>
    <message>
        <source>Spine</source>
        <translation>Wirbelsäule</translation>
    </message>
    <message>
        <source>Apply Mask Preset %1</source>
        <translation>Maskenvorgabe %1 anwenden</translation>
    </message>
    <message>
        <source>Mirror</source>
        <translation>Spiegeln</translation>
    </message>
    <message>
        <source>Swap left and right</source>
        <translation>Links und rechts vertauschen</translation>
    </message>
    <message>
        <source>Invert</source>
        <translation>Invertieren</translation>
    </message>
    <message>
        <source>Every weight w becomes 1 − w</source>
        <translation>Jedes Gewicht w wird zu 1 − w</translation>
    </message>
    <message>
        <source>Mirror Mask</source>
        <translation>Maske spiegeln</translation>
    </message>
    <message>
        <source>Invert Mask</source>
        <translation>Maske invertieren</translation>
    </message>
    <message>
        <source>Paint Mask</source>
        <translation>Maske malen</translation>
    </message>
    <message>
        <source>Set Joint Weight</source>
        <translation>Gelenkgewicht setzen</translation>
    </message>
    <message>
        <source>New Mask</source>
        <translation>Neue Maske</translation>
    </message>
    <message>
        <source>Name of the new mask:</source>
        <translation>Name der neuen Maske:</translation>
    </message>
    <message>
        <source>mask</source>
        <translation>Maske</translation>
    </message>
    <message>
        <source>Add Mask %1</source>
        <translation>Maske %1 hinzufügen</translation>
    </message>
    <message>
        <source>Rename Mask</source>
        <translation>Maske umbenennen</translation>
    </message>
    <message>
        <source>New name:</source>
        <translation>Neuer Name:</translation>
    </message>
    <message>
        <source>Delete Mask %1</source>
        <translation>Maske %1 löschen</translation>
    </message>
    <message>
        <source>New</source>
        <translation>Neu</translation>
    </message>
    <message>
        <source>Add a mask of the body&apos;s joints or of the face&apos;s regions</source>
        <translation>Eine Maske über die Gelenke des Körpers oder die Regionen des Gesichts hinzufügen</translation>
    </message>
    <message>
        <source>Body Mask…</source>
        <translation>Körpermaske…</translation>
    </message>
    <message>
        <source>Face Mask…</source>
        <translation>Gesichtsmaske…</translation>
    </message>
    <message>
        <source>Body</source>
        <translation>Körper</translation>
    </message>
    <message>
        <source>Whole Face</source>
        <translation>Ganzes Gesicht</translation>
    </message>
    <message>
        <source>Speech (mouth, tongue)</source>
        <translation>Sprache (Mund, Zunge)</translation>
    </message>
    <message>
        <source>Expression (eyes, brows, cheeks)</source>
        <translation>Ausdruck (Augen, Brauen, Wangen)</translation>
    </message>
    <message>
        <source>Eyes</source>
        <translation>Augen</translation>
    </message>
    <message>
        <source>Face</source>
        <translation>Gesicht</translation>
    </message>
    <message>
        <source>Set Face Weight</source>
        <translation>Gesichtsgewicht setzen</translation>
    </message>
    <message>
        <source>New Face Mask</source>
        <translation>Neue Gesichtsmaske</translation>
    </message>
    <message>
        <source>face mask</source>
        <translation>Gesichtsmaske</translation>
    </message>
</context>
<context>
    <name>thespis::editor::LightingDialog</name>
    <message>
        <source>Lighting</source>
        <translation>Beleuchtung</translation>
    </message>
    <message>
        <source>No probe: the default sky</source>
        <translation>Keine Sonde: der Standardhimmel</translation>
    </message>
    <message>
        <source>A light probe (HDR or EXR)</source>
        <translation>Eine Lichtsonde (HDR oder EXR)</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>Durchsuchen…</translation>
    </message>
    <message>
        <source>Latitude–longitude</source>
        <translation>Breite–Länge</translation>
    </message>
    <message>
        <source>Angular map (mirrored ball, unwrapped)</source>
        <translation>Winkelkarte (Spiegelkugel, abgewickelt)</translation>
    </message>
    <message>
        <source>Mirror ball (a photograph)</source>
        <translation>Spiegelkugel (ein Foto)</translation>
    </message>
    <message>
        <source>Vertical cross</source>
        <translation>Vertikales Kreuz</translation>
    </message>
    <message>
        <source>Layout:</source>
        <translation>Anordnung:</translation>
    </message>
    <message>
        <source>Turned about the vertical:</source>
        <translation>Gedreht um die Senkrechte:</translation>
    </message>
    <message>
        <source>Intensity:</source>
        <translation>Intensität:</translation>
    </message>
    <message>
        <source>The probe</source>
        <translation>Die Sonde</translation>
    </message>
    <message>
        <source>The light the characters receive</source>
        <translation>Das Licht, das die Figuren erhalten</translation>
    </message>
    <message>
        <source>Set Light</source>
        <translation>Licht festlegen</translation>
    </message>
    <message>
        <source>Choose a Light Probe</source>
        <translation>Lichtsonde auswählen</translation>
    </message>
    <message>
        <source>HDR images (*.hdr *.exr)</source>
        <translation>HDR-Bilder (*.hdr *.exr)</translation>
    </message>
    <message>
        <source>No file chosen.</source>
        <translation>Keine Datei gewählt.</translation>
    </message>
    <message>
        <source>%1 cannot be used as a light probe: %2</source>
        <translation>%1 kann nicht als Lichtsonde verwendet werden: %2</translation>
    </message>
    <message>
        <source>Choose a probe file.</source>
        <translation>Wählen Sie eine Sondendatei.</translation>
    </message>
    <message>
        <source>The default sky</source>
        <translation>Der Standardhimmel</translation>
    </message>
    <message>
        <source>Reading %1 and projecting its light…</source>
        <translation>%1 wird gelesen und sein Licht projiziert…</translation>
    </message>
</context>
<context>
    <name>thespis::editor::MessagesPanel</name>
    <message>
        <source>Double-click a message to show what it is about</source>
        <translation>Doppelklicken Sie auf eine Meldung, um anzuzeigen, worauf sie sich bezieht</translation>
    </message>
    <message>
        <source>Nothing to report.</source>
        <translation>Keine Meldungen.</translation>
    </message>
</context>
<context>
    <name>thespis::editor::PointingProperties</name>
    <message>
        <source>Points at</source>
        <translation>Zeigt auf</translation>
    </message>
    <message>
        <source>Aims the gesture&apos;s arm at a target while the action plays (BML&apos;s &lt;pointing&gt;)</source>
        <translation>Richtet den Arm der Geste auf ein Ziel, solange die Aktion spielt (BMLs &lt;pointing&gt;)</translation>
    </message>
    <message>
        <source>Right hand</source>
        <translation>Rechte Hand</translation>
    </message>
    <message>
        <source>Left hand</source>
        <translation>Linke Hand</translation>
    </message>
    <message>
        <source>Both hands</source>
        <translation>Beide Hände</translation>
    </message>
    <message>
        <source>Target:</source>
        <translation>Ziel:</translation>
    </message>
    <message>
        <source>With:</source>
        <translation>Mit:</translation>
    </message>
</context>
<context>
    <name>thespis::editor::PostureChartPanel</name>
    <message>
        <source>The character whose posture at the playhead is charted</source>
        <translation>Die Figur, deren Haltung an der Abspielposition dargestellt wird</translation>
    </message>
    <message>
        <source>Each bar: how far the pose is along one principal component of the upper body&apos;s posture space. The line: how far recorded motion typically goes along it. A hand-keyed pose shows more in the high components; the dependent-joint filter fades and mutes them.</source>
        <translation>Jeder Balken: wie weit die Pose entlang einer Hauptkomponente des Haltungsraums des Oberkörpers liegt. Die Linie: wie weit aufgenommene Bewegung typischerweise entlang ihr reicht. Eine von Hand animierte Pose zeigt mehr in den hohen Komponenten; der Filter für abhängige Gelenke blendet sie aus und schaltet sie stumm.</translation>
    </message>
    <message>
        <source>No character to chart.</source>
        <translation>Keine Figur darzustellen.</translation>
    </message>
    <message>
        <source>No posture bases: name a .pca file (thespis-cli train-pca) as the scenario&apos;s postureBases.</source>
        <translation>Keine Haltungsbasen: eine .pca-Datei (thespis-cli train-pca) als postureBases des Szenarios angeben.</translation>
    </message>
    <message>
        <source>The posture bases could not be read: %1</source>
        <translation>Die Haltungsbasen konnten nicht gelesen werden: %1</translation>
    </message>
    <message>
        <source>The character has no body motion to chart.</source>
        <translation>Die Figur hat keine Körperbewegung zum Darstellen.</translation>
    </message>
    <message>
        <source>Cannot chart this character&apos;s posture: %1</source>
        <translation>Die Haltung dieser Figur kann nicht dargestellt werden: %1</translation>
    </message>
    <message>
        <source>this pose |PC|</source>
        <translation>diese Pose |HK|</translation>
    </message>
    <message>
        <source>captured motion, typical (√eigenvalue)</source>
        <translation>aufgenommene Bewegung, typisch (√Eigenwert)</translation>
    </message>
    <message>
        <source>filter fades</source>
        <translation>Filter blendet aus</translation>
    </message>
    <message>
        <source>filter mutes</source>
        <translation>Filter schaltet stumm</translation>
    </message>
    <message>
        <source>%1 at %2 s — energy above PC %3: this pose %4 %, captured motion %5 %</source>
        <translation>%1 bei %2 s — Energie über HK %3: diese Pose %4 %, aufgenommene Bewegung %5 %</translation>
    </message>
    <message>
        <source>Nothing plays.</source>
        <translation>Nichts spielt.</translation>
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
        <translation>Zeitdehnung ×%1</translation>
    </message>
    <message>
        <source>time warp over %1</source>
        <translation>Zeitverzerrung über %1</translation>
    </message>
    <message>
        <source>loop forever</source>
        <translation>Endlosschleife</translation>
    </message>
    <message>
        <source>loop ×%1</source>
        <translation>Schleife ×%1</translation>
    </message>
    <message>
        <source>mirror left/right</source>
        <translation>links/rechts gespiegelt</translation>
    </message>
    <message>
        <source>moved to (%1, %2, %3) m</source>
        <translation>verschoben nach (%1, %2, %3) m</translation>
    </message>
    <message>
        <source>offset %1</source>
        <translation>versetzt um %1</translation>
    </message>
    <message>
        <source>trim %1 – %2</source>
        <translation>beschnitten auf %1 – %2</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Normalized (weighted average)</source>
        <translation>Normalisiert (gewichteter Mittelwert)</translation>
    </message>
    <message>
        <source>Additive (on top of the layers below)</source>
        <translation>Additiv (auf die darunterliegenden Ebenen)</translation>
    </message>
    <message>
        <source>Override (replaces by its weight)</source>
        <translation>Überschreibend (ersetzt gemäß ihrem Gewicht)</translation>
    </message>
    <message>
        <source>Hold the first and last pose outside the action</source>
        <translation>Erste und letzte Pose außerhalb der Aktion halten</translation>
    </message>
    <message>
        <source>Action of:</source>
        <translation>Aktion von:</translation>
    </message>
    <message>
        <source>Name:</source>
        <translation>Name:</translation>
    </message>
    <message>
        <source>Clip:</source>
        <translation>Clip:</translation>
    </message>
    <message>
        <source>Start:</source>
        <translation>Beginn:</translation>
    </message>
    <message>
        <source>Length:</source>
        <translation>Länge:</translation>
    </message>
    <message>
        <source>Fades:</source>
        <translation>Blenden:</translation>
    </message>
    <message>
        <source>Blend mode:</source>
        <translation>Mischmodus:</translation>
    </message>
    <message>
        <source>Body part:</source>
        <translation>Körperteil:</translation>
    </message>
    <message>
        <source>Modifiers:</source>
        <translation>Modifikatoren:</translation>
    </message>
    <message>
        <source>Rename Action</source>
        <translation>Aktion umbenennen</translation>
    </message>
    <message>
        <source>Change Clip</source>
        <translation>Clip ändern</translation>
    </message>
    <message>
        <source>Change Blend Mode</source>
        <translation>Mischmodus ändern</translation>
    </message>
    <message>
        <source>Change Body Part</source>
        <translation>Körperteil ändern</translation>
    </message>
    <message>
        <source>Change Outside Domain</source>
        <translation>Halten außerhalb der Aktion ändern</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>Move Action</source>
        <translation>Aktion verschieben</translation>
    </message>
    <message>
        <source>Move Action: %1</source>
        <translation>Aktion verschieben: %1</translation>
    </message>
    <message>
        <source>No scenario is open.</source>
        <translation>Kein Szenario geöffnet.</translation>
    </message>
    <message>
        <source>not saved yet</source>
        <translation>noch nicht gespeichert</translation>
    </message>
    <message numerus="yes">
        <source>%n character(s)</source>
        <translation>
            <numerusform>%n Figur</numerusform>
            <numerusform>%n Figuren</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n action(s)</source>
        <translation>
            <numerusform>%n Aktion</numerusform>
            <numerusform>%n Aktionen</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 ▸ %2%3</source>
        <translation>%1 ▸ %2%3</translation>
    </message>
    <message>
        <source> (locked)</source>
        <translation> (gesperrt)</translation>
    </message>
    <message>
        <source>Whole body</source>
        <translation>Ganzer Körper</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
    <message>
        <source>open-ended (plays until cut off)</source>
        <translation>offenes Ende (spielt bis zum Abbruch)</translation>
    </message>
    <message>
        <source>none (constant weight %1)</source>
        <translation>keine (konstantes Gewicht %1)</translation>
    </message>
    <message numerus="yes">
        <source>keyframed weight curve (%n key(s))</source>
        <translation>
            <numerusform>Gewichtskurve mit Keyframes (%n Schlüssel)</numerusform>
            <numerusform>Gewichtskurve mit Keyframes (%n Schlüssel)</numerusform>
        </translation>
    </message>
    <message>
        <source>in %1, out %2</source>
        <translation>ein %1, aus %2</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>Where it was recorded</source>
        <translation>Am Ort der Aufnahme</translation>
    </message>
    <message>
        <source>Where the character stands</source>
        <translation>Am Standort der Figur</translation>
    </message>
    <message>
        <source>Where the previous action leaves it</source>
        <translation>Wo die vorige Aktion die Figur hinterlässt</translation>
    </message>
    <message>
        <source>Where the motion&apos;s first frame puts the body on the floor (and which way it faces)</source>
        <translation>Wo das erste Bild der Bewegung den Körper auf den Boden stellt (und in welche Richtung er blickt)</translation>
    </message>
    <message>
        <source>forever</source>
        <translation>endlos</translation>
    </message>
    <message>
        <source> ×</source>
        <translation> ×</translation>
    </message>
    <message>
        <source>Each time on from where it ended (walks on)</source>
        <translation>Jedes Mal von dort weiter, wo sie endete (läuft weiter)</translation>
    </message>
    <message>
        <source>Starts:</source>
        <translation>Beginnt:</translation>
    </message>
    <message>
        <source>Plays:</source>
        <translation>Spielt:</translation>
    </message>
    <message>
        <source>Change Where the Action Starts</source>
        <translation>Startort der Aktion ändern</translation>
    </message>
    <message>
        <source>Change How Often the Action Plays</source>
        <translation>Wiederholungen der Aktion ändern</translation>
    </message>
    <message>
        <source>&lt;i&gt;No characters yet: Character ▸ Add Character… adds one, then File ▸ Import Motion… brings in its motion capture.&lt;/i&gt;</source>
        <translation>&lt;i&gt;Noch keine Figuren: Figur ▸ Figur hinzufügen… fügt eine hinzu, dann bringt Datei ▸ Bewegung importieren… ihre Motion-Capture-Daten.&lt;/i&gt;</translation>
    </message>
    <message>
        <source>&lt;i&gt;Select an action on the timeline, or a character in the scenario outline, to see and edit its properties.&lt;/i&gt;</source>
        <translation>&lt;i&gt;Wählen Sie eine Aktion auf der Zeitleiste oder eine Figur in der Szenario-Übersicht aus, um ihre Eigenschaften anzuzeigen und zu bearbeiten.&lt;/i&gt;</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;File: %2&lt;br&gt;%3, %4, %5 markers&lt;br&gt;Length: %6&lt;br&gt;&lt;br&gt;%7</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;Datei: %2&lt;br&gt;%3, %4, %5 Marker&lt;br&gt;Länge: %6&lt;br&gt;&lt;br&gt;%7</translation>
    </message>
    <message>
        <source>dependent joints follow (PCs kept to %1, muted above %2)</source>
        <translation>abhängige Gelenke folgen (HKs bis %1 erhalten, über %2 stumm)</translation>
    </message>
    <message>
        <source>Face regions:</source>
        <translation>Gesichtsregionen:</translation>
    </message>
    <message>
        <source>Whole face</source>
        <translation>Ganzes Gesicht</translation>
    </message>
    <message>
        <source>none (dominance weight curve, α %1)</source>
        <translation>keine (Dominanz-Gewichtskurve, α %1)</translation>
    </message>
    <message>
        <source>Change Gaze</source>
        <translation>Blick ändern</translation>
    </message>
    <message>
        <source>Change Pointing</source>
        <translation>Zeigen ändern</translation>
    </message>
</context>
<context>
    <name>thespis::editor::ScenarioTreeModel</name>
    <message>
        <source>stretch ×%1</source>
        <translation>Dehnung ×%1</translation>
    </message>
    <message>
        <source>time warp over %1 s</source>
        <translation>Zeitverzerrung über %1 s</translation>
    </message>
    <message>
        <source>loop forever</source>
        <translation>Endlosschleife</translation>
    </message>
    <message numerus="yes">
        <source>loop %n time(s)</source>
        <translation>
            <numerusform>%n-mal wiederholen</numerusform>
            <numerusform>%n-mal wiederholen</numerusform>
        </translation>
    </message>
    <message>
        <source>mirror</source>
        <translation>gespiegelt</translation>
    </message>
    <message>
        <source>move/rotate</source>
        <translation>verschoben/gedreht</translation>
    </message>
    <message>
        <source>offset %1 s</source>
        <translation>versetzt um %1 s</translation>
    </message>
    <message>
        <source>trim %1–%2 s</source>
        <translation>beschnitten auf %1–%2 s</translation>
    </message>
    <message>
        <source>, peak %1</source>
        <translation>, Spitze %1</translation>
    </message>
    <message>
        <source>constant %1</source>
        <translation>konstant %1</translation>
    </message>
    <message>
        <source>linear fade %1 / %2 s</source>
        <translation>lineare Blende %1 / %2 s</translation>
    </message>
    <message>
        <source>cubic fade %1 / %2 s</source>
        <translation>kubische Blende %1 / %2 s</translation>
    </message>
    <message>
        <source>linear ADSR %1 / %2 / %3 / %4</source>
        <translation>lineare ADSR %1 / %2 / %3 / %4</translation>
    </message>
    <message>
        <source>cubic ADSR %1 / %2 / %3 / %4</source>
        <translation>kubische ADSR %1 / %2 / %3 / %4</translation>
    </message>
    <message numerus="yes">
        <source>keyframed, %n key(s)</source>
        <translation>
            <numerusform>Keyframes, %n Schlüssel</numerusform>
            <numerusform>Keyframes, %n Schlüssel</numerusform>
        </translation>
    </message>
    <message>
        <source>normalized</source>
        <translation>normalisiert</translation>
    </message>
    <message>
        <source>additive</source>
        <translation>additiv</translation>
    </message>
    <message>
        <source>override</source>
        <translation>überschreibend</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Clip</source>
        <translation>Clip</translation>
    </message>
    <message>
        <source>Start (s)</source>
        <translation>Beginn (s)</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>Modus</translation>
    </message>
    <message>
        <source>Weight curve</source>
        <translation>Gewichtskurve</translation>
    </message>
    <message>
        <source>Mask</source>
        <translation>Maske</translation>
    </message>
    <message>
        <source>The motion clip an action plays</source>
        <translation>Der Bewegungsclip, den eine Aktion abspielt</translation>
    </message>
    <message>
        <source>When the action starts, in seconds from the start of the scenario</source>
        <translation>Wann die Aktion beginnt, in Sekunden ab Beginn des Szenarios</translation>
    </message>
    <message>
        <source>How the action or layer blends with the ones below it</source>
        <translation>Wie sich die Aktion oder Ebene mit den darunterliegenden mischt</translation>
    </message>
    <message>
        <source>How the action&apos;s weight rises and falls over its length.
Fades: fade-in / fade-out seconds. ADSR: attack / decay seconds, sustain level, release seconds.</source>
        <translation>Wie das Gewicht der Aktion über ihre Dauer steigt und fällt.
Blenden: Ein- / Ausblendung in Sekunden. ADSR: Anstieg / Abfall in Sekunden, Haltepegel, Ausklingen in Sekunden.</translation>
    </message>
    <message>
        <source>Which joints the action moves (empty: the whole body)</source>
        <translation>Welche Gelenke die Aktion bewegt (leer: der ganze Körper)</translation>
    </message>
    <message numerus="yes">
        <source>%n clip(s)</source>
        <translation>
            <numerusform>%n Clip</numerusform>
            <numerusform>%n Clips</numerusform>
        </translation>
    </message>
    <message>
        <source>Layer %1</source>
        <translation>Ebene %1</translation>
    </message>
    <message>
        <source>face layer</source>
        <translation>Gesichtsebene</translation>
    </message>
    <message>
        <source>body layer</source>
        <translation>Körperebene</translation>
    </message>
    <message>
        <source>base</source>
        <translation>Basis</translation>
    </message>
    <message>
        <source>Action %1</source>
        <translation>Aktion %1</translation>
    </message>
    <message>
        <source>whole body</source>
        <translation>ganzer Körper</translation>
    </message>
    <message>
        <source>Character “%1”: %2 skeleton</source>
        <translation>Figur „%1“: Skelett %2</translation>
    </message>
    <message>
        <source>The base layer: its actions blend with each other</source>
        <translation>Die Basisebene: ihre Aktionen mischen sich miteinander</translation>
    </message>
    <message>
        <source>Blends %1 over the layers above it</source>
        <translation>Mischt sich %1 über die Ebenen darüber</translation>
    </message>
    <message>
        <source>Plays clip “%1” from %2 s</source>
        <translation>Spielt Clip „%1“ ab %2 s</translation>
    </message>
    <message>
        <source>, without end</source>
        <translation>, ohne Ende</translation>
    </message>
    <message>
        <source> to %1 s</source>
        <translation> bis %1 s</translation>
    </message>
    <message>
        <source>Weight: %1</source>
        <translation>Gewicht: %1</translation>
    </message>
    <message>
        <source>Moves: %1</source>
        <translation>Bewegt: %1</translation>
    </message>
    <message>
        <source>the whole body</source>
        <translation>den ganzen Körper</translation>
    </message>
    <message>
        <source>mask “%1”</source>
        <translation>Maske „%1“</translation>
    </message>
    <message>
        <source>Modifiers: %1</source>
        <translation>Modifikatoren: %1</translation>
    </message>
    <message>
        <source>Playing now</source>
        <translation>Spielt gerade</translation>
    </message>
    <message>
        <source>Characters, their animation layers, and the actions in each layer.
A green dot marks an action that plays at the current time.</source>
        <translation>Figuren, ihre Animationsebenen und die Aktionen jeder Ebene.
Ein grüner Punkt markiert eine Aktion, die zur aktuellen Zeit spielt.</translation>
    </message>
    <message>
        <source>dependent joints</source>
        <translation>abhängige Gelenke</translation>
    </message>
    <message>
        <source>dominance α %1</source>
        <translation>Dominanz α %1</translation>
    </message>
    <message>
        <source>gaze layer</source>
        <translation>Blickebene</translation>
    </message>
</context>
<context>
    <name>thespis::editor::ScenePreview</name>
    <message>
        <source>The light probe could not be used (the default light shows instead): %1</source>
        <translation>Die Lichtsonde konnte nicht verwendet werden (stattdessen leuchtet das Standardlicht): %1</translation>
    </message>
</context>
<context>
    <name>thespis::editor::ScriptPanel</name>
    <message>
        <source>What the script prints, and its errors, show here.</source>
        <translation>Was das Skript ausgibt, und seine Fehler, erscheinen hier.</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Ausführen</translation>
    </message>
    <message>
        <source>Run the script on the scenario shown, while it plays (Ctrl+Return)</source>
        <translation>Das Skript auf dem gezeigten Szenario ausführen, während es abspielt (Strg+Eingabe)</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Anhalten</translation>
    </message>
    <message>
        <source>Stop the script now, even in a wait</source>
        <translation>Das Skript sofort anhalten, auch während es wartet</translation>
    </message>
    <message>
        <source>Clear Output</source>
        <translation>Ausgabe leeren</translation>
    </message>
    <message>
        <source>The scenario was rebuilt, so the script was stopped.</source>
        <translation>Das Szenario wurde neu aufgebaut, daher wurde das Skript angehalten.</translation>
    </message>
    <message>
        <source>Running…</source>
        <translation>Läuft…</translation>
    </message>
    <message>
        <source>— Run at %1 s —</source>
        <translation>— Gestartet bei %1 s —</translation>
    </message>
    <message>
        <source>Stopping…</source>
        <translation>Wird angehalten…</translation>
    </message>
    <message>
        <source>Finished.</source>
        <translation>Fertig.</translation>
    </message>
    <message>
        <source>Stopped.</source>
        <translation>Angehalten.</translation>
    </message>
    <message>
        <source>Open a scenario to run scripts on it.</source>
        <translation>Öffnen Sie ein Szenario, um Skripte darauf auszuführen.</translation>
    </message>
    <message>
        <source>Scratch, or a script kept in the scenario</source>
        <translation>Entwurf, oder ein im Szenario gespeichertes Skript</translation>
    </message>
    <message>
        <source>Scratch</source>
        <translation>Entwurf</translation>
    </message>
    <message>
        <source>Save to Scenario…</source>
        <translation>Im Szenario speichern…</translation>
    </message>
    <message>
        <source>Keep this script in the scenario (saved with it, one undo step)</source>
        <translation>Dieses Skript im Szenario behalten (wird mit ihm gespeichert, ein Rückgängig-Schritt)</translation>
    </message>
    <message>
        <source>Save Script to Scenario</source>
        <translation>Skript im Szenario speichern</translation>
    </message>
    <message>
        <source>Name of the script:</source>
        <translation>Name des Skripts:</translation>
    </message>
    <message>
        <source>script</source>
        <translation>skript</translation>
    </message>
    <message>
        <source>Not run: the scenario&apos;s scripts are not trusted.</source>
        <translation>Nicht ausgeführt: den Skripten des Szenarios wird nicht vertraut.</translation>
    </message>
    <message>
        <source>Save Script “%1”</source>
        <translation>Skript „%1“ speichern</translation>
    </message>
</context>
<context>
    <name>thespis::editor::SegmentPanel</name>
    <message>
        <source>The character whose body segments are tagged</source>
        <translation>Die Figur, deren Körpersegmente markiert werden</translation>
    </message>
    <message>
        <source>Filter segments…</source>
        <translation>Segmente filtern…</translation>
    </message>
    <message>
        <source>Show only the segments whose name or joint contains this text</source>
        <translation>Nur die Segmente anzeigen, deren Name oder Gelenk diesen Text enthält</translation>
    </message>
    <message>
        <source>Role:</source>
        <translation>Rolle:</translation>
    </message>
    <message>
        <source>Tag the selected segments as %1. %2</source>
        <translation>Die ausgewählten Segmente als %1 markieren. %2</translation>
    </message>
    <message>
        <source>Occluder</source>
        <translation>Verdecker</translation>
    </message>
    <message>
        <source>Vertices</source>
        <translation>Vertices</translation>
    </message>
    <message>
        <source>Triangles</source>
        <translation>Dreiecke</translation>
    </message>
    <message>
        <source>%1 of %2 selected</source>
        <translation>%1 von %2 ausgewählt</translation>
    </message>
    <message>
        <source>Click a segment in the viewport to select it (Ctrl toggles, Shift adds). Receivers are left out of the shadow proxy; occluders cast shadows but are not lit.</source>
        <translation>Klicken Sie im Ansichtsfenster auf ein Segment, um es auszuwählen (Strg schaltet um, Umschalt fügt hinzu). Empfänger bleiben aus dem Schatten-Proxy heraus; Verdecker werfen Schatten, werden aber nicht beleuchtet.</translation>
    </message>
</context>
<context>
    <name>thespis::editor::SegmentTableModel</name>
    <message>
        <source>No character is shown.</source>
        <translation>Keine Figur angezeigt.</translation>
    </message>
    <message numerus="yes">
        <source>Tag %n Segment(s)</source>
        <translation>
            <numerusform>%n Segment markieren</numerusform>
            <numerusform>%n Segmente markieren</numerusform>
        </translation>
    </message>
    <message>
        <source>None</source>
        <translation>Keine</translation>
    </message>
    <message>
        <source>Receiver</source>
        <translation>Empfänger</translation>
    </message>
    <message>
        <source>Occluder</source>
        <translation>Verdecker</translation>
    </message>
    <message>
        <source>Casts shadows and receives them.</source>
        <translation>Wirft Schatten und empfängt sie.</translation>
    </message>
    <message>
        <source>Receives shadows but casts none: left out of the shadow proxy (hair, loose clothes).</source>
        <translation>Empfängt Schatten, wirft aber keine: wird aus dem Schatten-Proxy ausgelassen (Haare, lose Kleidung).</translation>
    </message>
    <message>
        <source>Casts shadows but is not lit itself: no transfer is baked for it (props, phantom geometry).</source>
        <translation>Wirft Schatten, wird aber selbst nicht beleuchtet: Dafür wird kein Transfer gebacken (Requisiten, Phantomgeometrie).</translation>
    </message>
    <message>
        <source>(root)</source>
        <translation>(Wurzel)</translation>
    </message>
    <message>
        <source>Segment %1 follows joint %2</source>
        <translation>Segment %1 folgt Gelenk %2</translation>
    </message>
    <message>
        <source>Segment</source>
        <translation>Segment</translation>
    </message>
    <message>
        <source>Joint</source>
        <translation>Gelenk</translation>
    </message>
    <message>
        <source>Role</source>
        <translation>Rolle</translation>
    </message>
    <message>
        <source>Vertices</source>
        <translation>Vertices</translation>
    </message>
    <message>
        <source>Triangles</source>
        <translation>Dreiecke</translation>
    </message>
    <message>
        <source>The mesh segment (paper §6.1.3)</source>
        <translation>Das Mesh-Segment (Paper §6.1.3)</translation>
    </message>
    <message>
        <source>The H-Anim joint whose frame the segment follows</source>
        <translation>Das H-Anim-Gelenk, dessen Koordinatensystem das Segment folgt</translation>
    </message>
    <message>
        <source>Receiver: in shadow but casts none. Occluder: casts shadows, not lit. None: both.</source>
        <translation>Empfänger: im Schatten, wirft aber keinen. Verdecker: wirft Schatten, nicht beleuchtet. Keine: beides.</translation>
    </message>
    <message>
        <source>Vertices of the segment</source>
        <translation>Vertices des Segments</translation>
    </message>
    <message>
        <source>Triangles of the segment</source>
        <translation>Dreiecke des Segments</translation>
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
        <translation>Einheiten</translation>
    </message>
    <message>
        <source>This scenario has no characters yet.</source>
        <translation>Dieses Szenario hat noch keine Figuren.</translation>
    </message>
    <message>
        <source>No scenario is open.
Use File ▸ Open… (Ctrl+O) to open a .thespis file.</source>
        <translation>Kein Szenario geöffnet.
Öffnen Sie mit Datei ▸ Öffnen… (Strg+O) eine .thespis-Datei.</translation>
    </message>
</context>
<context>
    <name>thespis::editor::SpeechPanel</name>
    <message>
        <source>The character who speaks</source>
        <translation>Die Figur, die spricht</translation>
    </message>
    <message>
        <source>The espeak-ng voices installed</source>
        <translation>Die installierten espeak-ng-Stimmen</translation>
    </message>
    <message>
        <source> words/min</source>
        <translation> Wörter/min</translation>
    </message>
    <message>
        <source>Voice:</source>
        <translation>Stimme:</translation>
    </message>
    <message>
        <source>Rate:</source>
        <translation>Tempo:</translation>
    </message>
    <message>
        <source>Pitch:</source>
        <translation>Tonhöhe:</translation>
    </message>
    <message>
        <source>Visemes and their coarticulation</source>
        <translation>Viseme und ihre Koartikulation</translation>
    </message>
    <message>
        <source>Preview</source>
        <translation>Vorschau</translation>
    </message>
    <message>
        <source>Say it from the playhead, face and voice, without changing the scenario</source>
        <translation>Ab dem Abspielkopf sprechen, mit Gesicht und Stimme, ohne das Szenario zu ändern</translation>
    </message>
    <message>
        <source>Insert at Playhead</source>
        <translation>Am Abspielkopf einfügen</translation>
    </message>
    <message>
        <source>Lip Sync a Recording…</source>
        <translation>Aufnahme lippensynchronisieren…</translation>
    </message>
    <message>
        <source>Align a WAV with the text above as its transcript (empty: the words are recognised) and insert it</source>
        <translation>Eine WAV-Datei mit dem Text oben als Transkript abgleichen (leer: die Wörter werden erkannt) und einfügen</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Close-up</source>
        <translation>Nahaufnahme</translation>
    </message>
    <message>
        <source>Turn the 3D view to the speaker&apos;s face when previewing</source>
        <translation>Die 3D-Ansicht bei der Vorschau auf das Gesicht der sprechenden Figur richten</translation>
    </message>
    <message>
        <source>Nothing spoken yet</source>
        <translation>Noch nichts gesprochen</translation>
    </message>
    <message>
        <source>Lip Sync a Recording</source>
        <translation>Aufnahme lippensynchronisieren</translation>
    </message>
    <message>
        <source>Sound files (*.wav *.flac *.ogg)</source>
        <translation>Audiodateien (*.wav *.flac *.ogg)</translation>
    </message>
    <message numerus="yes">
        <source>Previewing %1 s of speech from %2 s: %n viseme(s)</source>
        <translation>
            <numerusform>Vorschau von %1 s Sprache ab %2 s: %n Visem</numerusform>
            <numerusform>Vorschau von %1 s Sprache ab %2 s: %n Viseme</numerusform>
        </translation>
    </message>
    <message>
        <source>; not in the gesticon: %1</source>
        <translation>; nicht im Gesticon: %1</translation>
    </message>
    <message>
        <source>Previewing</source>
        <translation>Vorschau läuft</translation>
    </message>
    <message>
        <source>Insert Speech</source>
        <translation>Sprechtext einfügen</translation>
    </message>
    <message>
        <source>Inserted</source>
        <translation>Eingefügt</translation>
    </message>
    <message numerus="yes">
        <source>Inserted at %1 s: %n viseme(s), %2 face and %3 body gesture(s).</source>
        <translation>
            <numerusform>Bei %1 s eingefügt: %n Visem, %2 Gesichts- und %3 Körpergeste(n).</numerusform>
            <numerusform>Bei %1 s eingefügt: %n Viseme, %2 Gesichts- und %3 Körpergeste(n).</numerusform>
        </translation>
    </message>
    <message>
        <source>Lip Sync Recording</source>
        <translation>Aufnahme lippensynchron einfügen</translation>
    </message>
    <message numerus="yes">
        <source>Lip-synced “%1”: %n word(s), %2 viseme(s).</source>
        <translation>
            <numerusform>„%1“ lippensynchronisiert: %n Wort, %2 Visem(e).</numerusform>
            <numerusform>„%1“ lippensynchronisiert: %n Wörter, %2 Visem(e).</numerusform>
        </translation>
    </message>
    <message>
        <source>What the character says. Gestures go around the words they span:
Are you &lt;begin_gesture id=&quot;g1&quot; anim=&quot;raise_eyebrows&quot;/&gt;really sure&lt;end_gesture id=&quot;g1&quot;/&gt;?
Or a BML block:
&lt;bml id=&quot;b1&quot;&gt;&lt;speech id=&quot;s1&quot;&gt;&lt;text&gt;Hello &lt;sync id=&quot;t1&quot;/&gt;there.&lt;/text&gt;&lt;/speech&gt;
&lt;gesture id=&quot;g1&quot; lexeme=&quot;BEAT&quot; stroke=&quot;s1:t1&quot;/&gt;&lt;gaze id=&quot;z1&quot; target=&quot;camera&quot;/&gt;&lt;/bml&gt;</source>
        <translation>Was die Figur sagt. Gesten umschließen die Wörter, die sie überspannen:
Bist du &lt;begin_gesture id=&quot;g1&quot; anim=&quot;raise_eyebrows&quot;/&gt;wirklich sicher&lt;end_gesture id=&quot;g1&quot;/&gt;?
Oder ein BML-Block:
&lt;bml id=&quot;b1&quot;&gt;&lt;speech id=&quot;s1&quot;&gt;&lt;text&gt;Hallo &lt;sync id=&quot;t1&quot;/&gt;du.&lt;/text&gt;&lt;/speech&gt;
&lt;gesture id=&quot;g1&quot; lexeme=&quot;BEAT&quot; stroke=&quot;s1:t1&quot;/&gt;&lt;gaze id=&quot;z1&quot; target=&quot;camera&quot;/&gt;&lt;/bml&gt;</translation>
    </message>
    <message>
        <source>Put the line, its visemes and its gestures (or the BML block&apos;s speech, gestures, head, face and gaze) on the timeline at the playhead (one undo step)</source>
        <translation>Den Satz, seine Viseme und Gesten (oder Sprache, Gesten, Kopf, Gesicht und Blick des BML-Blocks) am Abspielkopf in die Zeitleiste setzen (ein Rückgängig-Schritt)</translation>
    </message>
    <message numerus="yes">
        <source>Previewing BML block “%1” from %2 s to %3 s: %n behaviour(s)</source>
        <translation>
            <numerusform>Vorschau des BML-Blocks „%1“ von %2 s bis %3 s: %n Verhalten</numerusform>
            <numerusform>Vorschau des BML-Blocks „%1“ von %2 s bis %3 s: %n Verhalten</numerusform>
        </translation>
    </message>
    <message>
        <source>Insert BML</source>
        <translation>BML einfügen</translation>
    </message>
    <message numerus="yes">
        <source>Inserted BML from %1 s to %2 s: %n speech(es), %3 gesture(s), %4 head gesture(s), %5 face lexeme(s), %6 gaze(s).</source>
        <translation>
            <numerusform>BML von %1 s bis %2 s eingefügt: %n Sprechtext, %3 Geste(n), %4 Kopfgeste(n), %5 Gesichtslexem(e), %6 Blick(e).</numerusform>
            <numerusform>BML von %1 s bis %2 s eingefügt: %n Sprechtexte, %3 Geste(n), %4 Kopfgeste(n), %5 Gesichtslexem(e), %6 Blick(e).</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>thespis::editor::TargetChoice</name>
    <message>
        <source>The camera, a character (its eyes), a joint of one (&quot;Creon:r_radiocarpal&quot;) or a point in metres (&quot;0.5 1.6 2&quot;)</source>
        <translation>Die Kamera, eine Figur (ihre Augen), ein Gelenk einer Figur („Creon:r_radiocarpal“) oder ein Punkt in Metern („0.5 1.6 2“)</translation>
    </message>
    <message>
        <source>The camera (the viewer)</source>
        <translation>Die Kamera (der Betrachter)</translation>
    </message>
    <message>
        <source>%1&apos;s eyes</source>
        <translation>Augen von %1</translation>
    </message>
    <message>
        <source>%1&apos;s right hand</source>
        <translation>Rechte Hand von %1</translation>
    </message>
    <message>
        <source>%1&apos;s left hand</source>
        <translation>Linke Hand von %1</translation>
    </message>
</context>
<context>
    <name>thespis::editor::TimelinePanel</name>
    <message>
        <source>&amp;Delete</source>
        <translation>&amp;Löschen</translation>
    </message>
    <message>
        <source>Ripple De&amp;lete</source>
        <translation>Löschen und Lücke sc&amp;hließen</translation>
    </message>
    <message>
        <source>&amp;Copy</source>
        <translation>&amp;Kopieren</translation>
    </message>
    <message>
        <source>&amp;Paste</source>
        <translation>&amp;Einfügen</translation>
    </message>
    <message>
        <source>D&amp;uplicate</source>
        <translation>&amp;Duplizieren</translation>
    </message>
    <message>
        <source>&amp;Split at Playhead</source>
        <translation>Am Abspielkopf &amp;teilen</translation>
    </message>
    <message>
        <source>S&amp;napping</source>
        <translation>Einr&amp;asten</translation>
    </message>
    <message>
        <source>Snap to frames, clip edges, markers and the playhead (hold Ctrl while dragging to bypass)</source>
        <translation>An Bildern, Clipkanten, Markern und dem Abspielkopf einrasten (beim Ziehen Strg halten, um es zu umgehen)</translation>
    </message>
    <message numerus="yes">
        <source>Move %n Action(s)</source>
        <translation>
            <numerusform>%n Aktion verschieben</numerusform>
            <numerusform>%n Aktionen verschieben</numerusform>
        </translation>
    </message>
    <message>
        <source>Trim Action</source>
        <translation>Aktion beschneiden</translation>
    </message>
    <message>
        <source>Change Fade In</source>
        <translation>Einblendung ändern</translation>
    </message>
    <message>
        <source>Change Fade Out</source>
        <translation>Ausblendung ändern</translation>
    </message>
    <message>
        <source>Mute Layer</source>
        <translation>Ebene stummschalten</translation>
    </message>
    <message>
        <source>Unmute Layer</source>
        <translation>Stummschaltung der Ebene aufheben</translation>
    </message>
    <message>
        <source>Solo Layer</source>
        <translation>Ebene solo schalten</translation>
    </message>
    <message>
        <source>Unsolo Layer</source>
        <translation>Solo der Ebene aufheben</translation>
    </message>
    <message>
        <source>Lock Layer</source>
        <translation>Ebene sperren</translation>
    </message>
    <message>
        <source>Unlock Layer</source>
        <translation>Ebene entsperren</translation>
    </message>
    <message>
        <source>Marker %1</source>
        <translation>Marker %1</translation>
    </message>
    <message>
        <source>Add Marker</source>
        <translation>Marker hinzufügen</translation>
    </message>
    <message>
        <source>Move Marker</source>
        <translation>Marker verschieben</translation>
    </message>
    <message>
        <source>Remove Marker</source>
        <translation>Marker entfernen</translation>
    </message>
    <message>
        <source>Add Action %1</source>
        <translation>Aktion %1 hinzufügen</translation>
    </message>
    <message numerus="yes">
        <source>Ripple Delete %n Action(s)</source>
        <translation>
            <numerusform>%n Aktion löschen und Lücke schließen</numerusform>
            <numerusform>%n Aktionen löschen und Lücke schließen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Delete %n Action(s)</source>
        <translation>
            <numerusform>%n Aktion löschen</numerusform>
            <numerusform>%n Aktionen löschen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Paste %n Action(s)</source>
        <translation>
            <numerusform>%n Aktion einfügen</numerusform>
            <numerusform>%n Aktionen einfügen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Duplicate %n Action(s)</source>
        <translation>
            <numerusform>%n Aktion duplizieren</numerusform>
            <numerusform>%n Aktionen duplizieren</numerusform>
        </translation>
    </message>
    <message>
        <source>Select one action to split at the playhead.</source>
        <translation>Wählen Sie eine Aktion aus, um sie am Abspielkopf zu teilen.</translation>
    </message>
    <message>
        <source>Split Action</source>
        <translation>Aktion teilen</translation>
    </message>
    <message>
        <source>Add Idle Motion</source>
        <translation>Ruhebewegung hinzufügen</translation>
    </message>
</context>
<context>
    <name>thespis::editor::VisemeTable</name>
    <message>
        <source>Viseme</source>
        <translation>Visem</translation>
    </message>
    <message>
        <source>Phonemes</source>
        <translation>Phoneme</translation>
    </message>
    <message>
        <source>α</source>
        <translation>α</translation>
    </message>
    <message>
        <source>Weight</source>
        <translation>Gewicht</translation>
    </message>
    <message>
        <source>Spread</source>
        <translation>Ausdehnung</translation>
    </message>
    <message>
        <source>Dominance α (paper eq. 3): larger keeps the mouth shape to its own phoneme</source>
        <translation>Dominanz α (Gleichung 3 im Paper): Ein größerer Wert hält die Mundform bei ihrem eigenen Phonem</translation>
    </message>
    <message>
        <source>How far the shape is reached at the phoneme&apos;s centre (0 … 1)</source>
        <translation>Wie weit die Form in der Mitte des Phonems erreicht wird (0 … 1)</translation>
    </message>
    <message>
        <source>How far the shape reaches past its phoneme, as a share of the phoneme&apos;s length on each side (0 … 2)</source>
        <translation>Wie weit die Form über ihr Phonem hinausreicht, als Anteil der Phonemlänge auf jeder Seite (0 … 2)</translation>
    </message>
    <message>
        <source>Load…</source>
        <translation>Laden…</translation>
    </message>
    <message>
        <source>Save…</source>
        <translation>Speichern…</translation>
    </message>
    <message>
        <source>Load Visemes</source>
        <translation>Viseme laden</translation>
    </message>
    <message>
        <source>Viseme sets (*.json)</source>
        <translation>Visem-Sätze (*.json)</translation>
    </message>
    <message>
        <source>Save Visemes</source>
        <translation>Viseme speichern</translation>
    </message>
    <message>
        <source>Shows as (MPEG-4)</source>
        <translation>Erscheint als (MPEG-4)</translation>
    </message>
    <message>
        <source>The MPEG-4 viseme (1 … 14) the face shows this one as; 0 keeps the mouth at rest</source>
        <translation>Das MPEG-4-Visem (1 … 14), als das das Gesicht dieses zeigt; 0 lässt den Mund in Ruhe</translation>
    </message>
    <message>
        <source>Start again from a built-in set: MPEG-4&apos;s 14, Oculus Lipsync&apos;s 15 or Microsoft&apos;s SAPI 21</source>
        <translation>Neu beginnen mit einem eingebauten Satz: den 14 von MPEG-4, den 15 von Oculus Lipsync oder den 21 von Microsofts SAPI</translation>
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
        <translation>Eingebaut:</translation>
    </message>
</context>
<context>
    <name>thespis::editor::newDocument</name>
    <message>
        <source>New scenario</source>
        <translation>Neues Szenario</translation>
    </message>
    <message>
        <source>Actor</source>
        <translation>Darsteller</translation>
    </message>
</context>
<context>
    <name>thespis::studio::MainWindow</name>
    <message>
        <source>&amp;Open…</source>
        <translation>&amp;Öffnen…</translation>
    </message>
    <message>
        <source>&amp;Reload</source>
        <translation>&amp;Neu laden</translation>
    </message>
    <message>
        <source>Read the scenario file again, e.g. after editing it elsewhere</source>
        <translation>Die Szenariodatei erneut lesen, z. B. nachdem sie anderswo bearbeitet wurde</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>&amp;Play/Pause</source>
        <translation>&amp;Wiedergabe/Pause</translation>
    </message>
    <message>
        <source>Go to &amp;Start</source>
        <translation>Zum &amp;Anfang</translation>
    </message>
    <message>
        <source>&amp;Loop</source>
        <translation>&amp;Schleife</translation>
    </message>
    <message>
        <source>&amp;Front and Side</source>
        <translation>&amp;Vorne und Seite</translation>
    </message>
    <message>
        <source>F&amp;ront</source>
        <translation>V&amp;orne</translation>
    </message>
    <message>
        <source>&amp;Side</source>
        <translation>S&amp;eite</translation>
    </message>
    <message>
        <source>&amp;About Thespis Studio</source>
        <translation>&amp;Über Thespis Studio</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>Über &amp;Qt</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>&amp;Playback</source>
        <translation>&amp;Wiedergabe</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>Stick figures</source>
        <translation>Strichfiguren</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>Scenario</source>
        <translation>Szenario</translation>
    </message>
    <message>
        <source>Scenario &amp;Outline</source>
        <translation>Szenario-&amp;Übersicht</translation>
    </message>
    <message>
        <source>How often the preview is redrawn</source>
        <translation>Wie oft die Vorschau neu gezeichnet wird</translation>
    </message>
    <message>
        <source>Preview: 000 fps</source>
        <translation>Vorschau: 000 B/s</translation>
    </message>
    <message>
        <source>Could not open “%1”.</source>
        <translation>„%1“ konnte nicht geöffnet werden.</translation>
    </message>
    <message>
        <source>Could not open %1</source>
        <translation>%1 konnte nicht geöffnet werden</translation>
    </message>
    <message numerus="yes">
        <source>Opened %1: %n character(s)</source>
        <translation>
            <numerusform>%1 geöffnet: %n Figur</numerusform>
            <numerusform>%1 geöffnet: %n Figuren</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>, %n action(s)</source>
        <translation>
            <numerusform>, %n Aktion</numerusform>
            <numerusform>, %n Aktionen</numerusform>
        </translation>
    </message>
    <message>
        <source>, %1 s long. Press Space to play.</source>
        <translation>, %1 s lang. Leertaste spielt ab.</translation>
    </message>
    <message>
        <source>Open Scenario</source>
        <translation>Szenario öffnen</translation>
    </message>
    <message>
        <source>About Thespis Studio</source>
        <translation>Über Thespis Studio</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Thespis Studio %1&lt;/h3&gt;&lt;p&gt;An authoring studio for interactive virtual humans in mixed reality: blending schedules, speech and gestures, precomputed lighting, and AR preview.&lt;/p&gt;&lt;p&gt;Built on the MIRAnim blending engine described by Egges, Papagiannakis and Magnenat-Thalmann, &lt;i&gt;Presence and interaction in mixed reality environments&lt;/i&gt;, The Visual Computer, 2007.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Thespis Studio %1&lt;/h3&gt;&lt;p&gt;Ein Autorenstudio für interaktive virtuelle Menschen in gemischter Realität: Überblendungspläne, Sprache und Gesten, vorberechnete Beleuchtung und AR-Vorschau.&lt;/p&gt;&lt;p&gt;Beruht auf der MIRAnim-Überblendungs-Engine, beschrieben von Egges, Papagiannakis und Magnenat-Thalmann, &lt;i&gt;Presence and interaction in mixed reality environments&lt;/i&gt;, The Visual Computer, 2007.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>&amp;Pause</translation>
    </message>
    <message>
        <source>&amp;Play</source>
        <translation>&amp;Abspielen</translation>
    </message>
    <message>
        <source>Paused</source>
        <translation>Angehalten</translation>
    </message>
    <message>
        <source>Preview: %1 fps</source>
        <translation>Vorschau: %1 B/s</translation>
    </message>
    <message>
        <source>Playing</source>
        <translation>Spielt</translation>
    </message>
    <message>
        <source>Thespis Studio</source>
        <translation>Thespis Studio</translation>
    </message>
    <message>
        <source>Drag to orbit, right-drag or wheel to zoom, middle-drag to pan, double-click for the home view</source>
        <translation>Ziehen zum Umkreisen, rechts ziehen oder Mausrad zum Zoomen, mittig ziehen zum Verschieben, Doppelklick für die Ausgangsansicht</translation>
    </message>
    <message>
        <source>No 3D view: this display offers no OpenGL.
The Skeletons tab shows the animation; thespis-cli render draws the scene headless.</source>
        <translation>Keine 3D-Ansicht: Diese Anzeige bietet kein OpenGL.
Der Reiter Skelette zeigt die Animation; thespis-cli render zeichnet die Szene ohne Anzeige.</translation>
    </message>
    <message>
        <source>Scene</source>
        <translation>Szene</translation>
    </message>
    <message>
        <source>Skeletons</source>
        <translation>Skelette</translation>
    </message>
    <message>
        <source>&amp;PRT Lighting</source>
        <translation>&amp;PRT-Beleuchtung</translation>
    </message>
    <message>
        <source>P&amp;hong Lighting</source>
        <translation>P&amp;hong-Beleuchtung</translation>
    </message>
    <message>
        <source>&amp;Unlit</source>
        <translation>&amp;Unbeleuchtet</translation>
    </message>
    <message>
        <source>Precomputed radiance transfer: soft light and self-shadowing from the light probe</source>
        <translation>Vorberechneter Strahlungstransfer: weiches Licht und Eigenschatten aus der Lichtsonde</translation>
    </message>
    <message>
        <source>One directional light and ambient, for comparison with PRT</source>
        <translation>Ein gerichtetes Licht und Umgebungslicht, zum Vergleich mit PRT</translation>
    </message>
    <message>
        <source>&amp;Ground</source>
        <translation>&amp;Boden</translation>
    </message>
    <message>
        <source>&amp;Home View</source>
        <translation>&amp;Ausgangsansicht</translation>
    </message>
    <message>
        <source>The 3D view is empty: %1</source>
        <translation>Die 3D-Ansicht ist leer: %1</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>N&amp;eu</translation>
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
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederholen</translation>
    </message>
    <message>
        <source>Go to &amp;End</source>
        <translation>Zum &amp;Ende</translation>
    </message>
    <message>
        <source>Previous &amp;Frame</source>
        <translation>&amp;Vorheriges Bild</translation>
    </message>
    <message>
        <source>&amp;Next Frame</source>
        <translation>&amp;Nächstes Bild</translation>
    </message>
    <message>
        <source>&amp;Preferences…</source>
        <translation>Ein&amp;stellungen…</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <source>Timeline</source>
        <translation>Zeitleiste</translation>
    </message>
    <message>
        <source>Curve Editor</source>
        <translation>Kurveneditor</translation>
    </message>
    <message>
        <source>Properties</source>
        <translation>Eigenschaften</translation>
    </message>
    <message>
        <source>Segments</source>
        <translation>Segmente</translation>
    </message>
    <message>
        <source>Bake</source>
        <translation>Backen</translation>
    </message>
    <message>
        <source>Clip Library</source>
        <translation>Clipbibliothek</translation>
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
        <translation>Ein neues Szenario konnte nicht begonnen werden.</translation>
    </message>
    <message>
        <source>Could not save “%1”.</source>
        <translation>„%1“ konnte nicht gespeichert werden.</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <source>Save Scenario As</source>
        <translation>Szenario speichern unter</translation>
    </message>
    <message>
        <source>Thespis scenarios (*.thespis)</source>
        <translation>Thespis-Szenarien (*.thespis)</translation>
    </message>
    <message>
        <source>Unsaved Changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <source>“%1” has changes that are not saved. Save them?</source>
        <translation>„%1“ enthält ungespeicherte Änderungen. Möchten Sie sie speichern?</translation>
    </message>
    <message>
        <source>an unsaved scenario</source>
        <translation>ein ungespeichertes Szenario</translation>
    </message>
    <message>
        <source>Recover Unsaved Work</source>
        <translation>Ungespeicherte Arbeit wiederherstellen</translation>
    </message>
    <message>
        <source>Thespis Studio did not close properly. Recover the changes to %1 autosaved at %2?</source>
        <translation>Thespis Studio wurde nicht ordnungsgemäß beendet. Die um %2 automatisch gespeicherten Änderungen für %1 wiederherstellen?</translation>
    </message>
    <message>
        <source>Recovered %1; save it to keep it.</source>
        <translation>Wiederhergestellt: %1; speichern Sie, um die Änderungen zu behalten.</translation>
    </message>
    <message>
        <source>Could not recover %1.</source>
        <translation>Wiederherstellen nicht möglich: %1.</translation>
    </message>
    <message>
        <source>Main Toolbar</source>
        <translation>Hauptwerkzeugleiste</translation>
    </message>
    <message>
        <source>Start a new scenario: empty, or with one character standing</source>
        <translation>Ein neues Szenario beginnen: leer oder mit einer stehenden Figur</translation>
    </message>
    <message>
        <source>&amp;Character</source>
        <translation>&amp;Figur</translation>
    </message>
    <message>
        <source>Messages</source>
        <translation>Meldungen</translation>
    </message>
    <message>
        <source>Messages (%1)</source>
        <translation>Meldungen (%1)</translation>
    </message>
    <message numerus="yes">
        <source>%n warning(s): see Messages.</source>
        <translation>
            <numerusform>%n Warnung: siehe Meldungen.</numerusform>
            <numerusform>%n Warnungen: siehe Meldungen.</numerusform>
        </translation>
    </message>
    <message>
        <source>New Scenario</source>
        <translation>Neues Szenario</translation>
    </message>
    <message>
        <source>What should the new scenario start with?</source>
        <translation>Womit soll das neue Szenario beginnen?</translation>
    </message>
    <message>
        <source>Either way, File ▸ Import Motion… brings in motion capture, Character ▸ Add Character… more characters, and View ▸ Lighting… a light probe.</source>
        <translation>In beiden Fällen holen Sie mit Datei ▸ Bewegung importieren… Motion-Capture-Daten, mit Figur ▸ Figur hinzufügen… weitere Figuren und mit Ansicht ▸ Beleuchtung… eine Lichtsonde hinzu.</translation>
    </message>
    <message>
        <source>One Character, Standing</source>
        <translation>Eine stehende Figur</translation>
    </message>
    <message>
        <source>Empty</source>
        <translation>Leer</translation>
    </message>
    <message>
        <source>Script</source>
        <translation>Skript</translation>
    </message>
    <message>
        <source>The script ran to its end.</source>
        <translation>Das Skript ist bis zum Ende gelaufen.</translation>
    </message>
    <message>
        <source>Script: %1</source>
        <translation>Skript: %1</translation>
    </message>
    <message>
        <source>Run Scripts From This File?</source>
        <translation>Skripte aus dieser Datei ausführen?</translation>
    </message>
    <message>
        <source>“%1” keeps Python scripts. A script can do anything your user account can: read, change and delete files, or use the network.

Run the scenario&apos;s scripts only if you trust where this file came from. Your answer is remembered for this file as it is now.</source>
        <translation>„%1“ enthält Python-Skripte. Ein Skript kann alles, was Ihr Benutzerkonto kann: Dateien lesen, ändern und löschen oder das Netzwerk nutzen.

Führen Sie die Skripte des Szenarios nur aus, wenn Sie der Herkunft dieser Datei vertrauen. Ihre Antwort wird für diese Datei in ihrem jetzigen Zustand gespeichert.</translation>
    </message>
    <message>
        <source>Trust This File and Run</source>
        <translation>Dieser Datei vertrauen und ausführen</translation>
    </message>
    <message>
        <source>Posture PCs</source>
        <translation>Haltungs-HK</translation>
    </message>
    <message>
        <source>AR Preview</source>
        <translation>AR-Vorschau</translation>
    </message>
    <message>
        <source>Write the scenario and every file it names into one package (.thespkg)</source>
        <translation>Das Szenario und alle Dateien, die es nennt, in ein Paket (.thespkg) schreiben</translation>
    </message>
    <message>
        <source>Open a scenario file (.thespis) or a package (.thespkg)</source>
        <translation>Eine Szenariodatei (.thespis) oder ein Paket (.thespkg) öffnen</translation>
    </message>
    <message>
        <source>Thespis scenarios and packages (*.thespis *.thespkg);;All files (*)</source>
        <translation>Thespis-Szenarien und -Pakete (*.thespis *.thespkg);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Exported %1</source>
        <translation>%1 exportiert</translation>
    </message>
    <message>
        <source>Write a character&apos;s motion as glTF (.glb, with the character) or BVH, for Blender, three.js and game engines</source>
        <translation>Die Bewegung einer Figur als glTF (.glb, mit der Figur) oder BVH schreiben, für Blender, three.js und Spiel-Engines</translation>
    </message>
    <message>
        <source>&amp;Package…</source>
        <translation>&amp;Paket…</translation>
    </message>
    <message>
        <source>&amp;Motion (glTF or BVH)…</source>
        <translation>&amp;Bewegung (glTF oder BVH)…</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>E&amp;xportieren</translation>
    </message>
    <message>
        <source>&amp;Close-up</source>
        <translation>&amp;Nahaufnahme</translation>
    </message>
    <message>
        <source>This character has no head to frame.</source>
        <translation>Diese Figur hat keinen Kopf, der sich ins Bild setzen lässt.</translation>
    </message>
    <message>
        <source>No characters</source>
        <translation>Keine Figuren</translation>
    </message>
    <message>
        <source>Masks</source>
        <translation>Masken</translation>
    </message>
    <message>
        <source>Face Pose</source>
        <translation>Gesichtspose</translation>
    </message>
    <message>
        <source>Speech</source>
        <translation>Sprache</translation>
    </message>
    <message>
        <source>Conversation</source>
        <translation>Gespräch</translation>
    </message>
</context>
<context>
    <name>thespis::studio::PreferencesDialog</name>
    <message>
        <source>Preferences</source>
        <translation>Einstellungen</translation>
    </message>
    <message>
        <source>System default (%1)</source>
        <translation>Systemstandard (%1)</translation>
    </message>
    <message>
        <source>&amp;Language:</source>
        <translation>&amp;Sprache:</translation>
    </message>
    <message>
        <source>The new language is used from the next start of the studio.</source>
        <translation>Die neue Sprache wird ab dem nächsten Start des Studios verwendet.</translation>
    </message>
    <message>
        <source> min</source>
        <translation> min</translation>
    </message>
    <message>
        <source>How often open work is copied to a recovery file, offered after a crash</source>
        <translation>Wie oft offene Arbeit in eine Wiederherstellungsdatei kopiert wird, die nach einem Absturz angeboten wird</translation>
    </message>
    <message>
        <source>&amp;Autosave every:</source>
        <translation>&amp;Automatisch speichern alle:</translation>
    </message>
</context>
<context>
    <name>thespis::widgets::CurveView</name>
    <message>
        <source>No curves to show</source>
        <translation>Keine Kurven anzuzeigen</translation>
    </message>
    <message>
        <source>Click a key to select it, drag to move it; double-click a curve to add a key. Wheel: zoom (Ctrl: values only, Shift: time only); middle-drag: pan; F: frame all.</source>
        <translation>Klicken Sie auf einen Schlüssel, um ihn auszuwählen, und ziehen Sie ihn, um ihn zu verschieben; Doppelklick auf eine Kurve fügt einen Schlüssel hinzu. Mausrad: Zoomen (Strg: nur Werte, Umschalt: nur Zeit); mittig ziehen: Verschieben; F: alles einpassen.</translation>
    </message>
    <message>
        <source>Tangents</source>
        <translation>Tangenten</translation>
    </message>
    <message>
        <source>Auto Clamped</source>
        <translation>Automatisch begrenzt</translation>
    </message>
    <message>
        <source>Linear</source>
        <translation>Linear</translation>
    </message>
    <message>
        <source>Constant</source>
        <translation>Konstant</translation>
    </message>
    <message>
        <source>Free</source>
        <translation>Frei</translation>
    </message>
    <message>
        <source>Broken</source>
        <translation>Gebrochen</translation>
    </message>
    <message>
        <source>Smooth tangents that never overshoot neighbouring keys</source>
        <translation>Glatte Tangenten, die benachbarte Schlüssel nie überschießen</translation>
    </message>
    <message>
        <source>Straight lines between keys</source>
        <translation>Gerade Linien zwischen Schlüsseln</translation>
    </message>
    <message>
        <source>Hold the value until the next key</source>
        <translation>Den Wert bis zum nächsten Schlüssel halten</translation>
    </message>
    <message>
        <source>Smooth tangents you drag, the same on both sides</source>
        <translation>Glatte Tangenten zum Ziehen, auf beiden Seiten gleich</translation>
    </message>
    <message>
        <source>Tangents you drag, each side on its own</source>
        <translation>Tangenten zum Ziehen, jede Seite für sich</translation>
    </message>
    <message>
        <source>Delete Keys</source>
        <translation>Schlüssel löschen</translation>
    </message>
    <message>
        <source>Frame All</source>
        <translation>Alles einpassen</translation>
    </message>
    <message>
        <source>%1, key %2
Time %3 s, value %4
Tangents: %5</source>
        <translation>%1, Schlüssel %2
Zeit %3 s, Wert %4
Tangenten: %5</translation>
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
        <translation>Kein Skelett</translation>
    </message>
    <message>
        <source>R</source>
        <comment>the character&apos;s right side</comment>
        <translation>R</translation>
    </message>
    <message>
        <source>L</source>
        <comment>the character&apos;s left side</comment>
        <translation>L</translation>
    </message>
    <message>
        <source>Drag to paint · right-drag paints 0</source>
        <translation>Ziehen zum Malen · rechts ziehen malt 0</translation>
    </message>
    <message>
        <source>Joint</source>
        <translation>Gelenk</translation>
    </message>
    <message>
        <source>Weight</source>
        <translation>Gewicht</translation>
    </message>
    <message>
        <source>Brush weight</source>
        <translation>Pinselgewicht</translation>
    </message>
    <message>
        <source>The weight a left-button stroke paints (the right button paints 0)</source>
        <translation>Das Gewicht, das ein Strich mit der linken Maustaste malt (die rechte Maustaste malt 0)</translation>
    </message>
    <message>
        <source>Radius</source>
        <translation>Radius</translation>
    </message>
    <message>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <source>Radius of the brush in the picture</source>
        <translation>Radius des Pinsels im Bild</translation>
    </message>
    <message>
        <source>%1: set by the mask</source>
        <translation>%1: von der Maske gesetzt</translation>
    </message>
    <message>
        <source>%1: inherited</source>
        <translation>%1: geerbt</translation>
    </message>
    <message>
        <source>Set to 1</source>
        <translation>Auf 1 setzen</translation>
    </message>
    <message>
        <source>Set to 0.5</source>
        <translation>Auf 0,5 setzen</translation>
    </message>
    <message>
        <source>Set to 0</source>
        <translation>Auf 0 setzen</translation>
    </message>
</context>
<context>
    <name>thespis::widgets::OsgViewport</name>
    <message>
        <source>No OpenGL context could be created for the 3D view.</source>
        <translation>Für die 3D-Ansicht ließ sich kein OpenGL-Kontext erzeugen.</translation>
    </message>
    <message>
        <source>The 3D view got a core-profile OpenGL context; it needs a compatibility profile.</source>
        <translation>Die 3D-Ansicht erhielt einen OpenGL-Kontext im Core-Profil; sie braucht ein Kompatibilitätsprofil.</translation>
    </message>
    <message>
        <source>The 3D view needs OpenGL 2.1 or newer; this system offers %1.%2.</source>
        <translation>Die 3D-Ansicht braucht OpenGL 2.1 oder neuer; dieses System bietet %1.%2.</translation>
    </message>
</context>
<context>
    <name>thespis::widgets::PoseView</name>
    <message>
        <source>Nothing to show</source>
        <translation>Nichts anzuzeigen</translation>
    </message>
    <message>
        <source>Side (from the right)</source>
        <translation>Seite (von rechts)</translation>
    </message>
    <message>
        <source>Front</source>
        <translation>Vorne</translation>
    </message>
</context>
<context>
    <name>thespis::widgets::TimelineView</name>
    <message>
        <source>%1 fps</source>
        <translation>%1 B/s</translation>
    </message>
    <message>
        <source>Remove Marker “%1”</source>
        <translation>Marker „%1“ entfernen</translation>
    </message>
    <message>
        <source>Add Marker Here</source>
        <translation>Marker hier hinzufügen</translation>
    </message>
    <message>
        <source>%1
%2 – open end</source>
        <translation>%1
%2 – offenes Ende</translation>
    </message>
    <message>
        <source>%1
%2 – %3 (%4)</source>
        <translation>%1
%2 – %3 (%4)</translation>
    </message>
    <message>
        <source>The track is locked</source>
        <translation>Die Spur ist gesperrt</translation>
    </message>
    <message>
        <source>Mute: leave this track out of playback</source>
        <translation>Stumm: diese Spur bei der Wiedergabe auslassen</translation>
    </message>
    <message>
        <source>Solo: play only the soloed tracks</source>
        <translation>Solo: nur die Solo-Spuren abspielen</translation>
    </message>
    <message>
        <source>Lock: protect this track&apos;s clips from edits</source>
        <translation>Sperren: die Clips dieser Spur vor Bearbeitung schützen</translation>
    </message>
    <message>
        <source>%1 at %2</source>
        <translation>%1 bei %2</translation>
    </message>
</context>
<context>
    <name>thespis::widgets::TransportBar</name>
    <message>
        <source>Go to the start (Home)</source>
        <translation>Zum Anfang (Pos1)</translation>
    </message>
    <message>
        <source>Loop</source>
        <translation>Schleife</translation>
    </message>
    <message>
        <source>Start again at the end of the scenario (L)</source>
        <translation>Am Ende des Szenarios von vorn beginnen (L)</translation>
    </message>
    <message>
        <source>Drag to scrub through the scenario</source>
        <translation>Ziehen, um durch das Szenario zu fahren</translation>
    </message>
    <message>
        <source>Current time / length of the scenario (minutes:seconds.milliseconds)</source>
        <translation>Aktuelle Zeit / Länge des Szenarios (Minuten:Sekunden.Millisekunden)</translation>
    </message>
    <message>
        <source>frame %1</source>
        <translation>Bild %1</translation>
    </message>
    <message>
        <source>Frame number at %1 frames per second</source>
        <translation>Bildnummer bei %1 Bildern pro Sekunde</translation>
    </message>
    <message>
        <source>Pause (Space)</source>
        <translation>Pause (Leertaste)</translation>
    </message>
    <message>
        <source>Play (Space)</source>
        <translation>Abspielen (Leertaste)</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Abspielen</translation>
    </message>
    <message>
        <source>Previous frame (Left arrow)</source>
        <translation>Vorheriges Bild (Pfeil links)</translation>
    </message>
    <message>
        <source>Next frame (Right arrow)</source>
        <translation>Nächstes Bild (Pfeil rechts)</translation>
    </message>
    <message>
        <source>Go to the end (End)</source>
        <translation>Zum Ende (Ende)</translation>
    </message>
    <message>
        <source>Frames per second for frame numbers, frame steps and snapping</source>
        <translation>Bilder pro Sekunde für Bildnummern, Bildschritte und Einrasten</translation>
    </message>
    <message>
        <source>%1 fps</source>
        <translation>%1 B/s</translation>
    </message>
</context>
</TS>

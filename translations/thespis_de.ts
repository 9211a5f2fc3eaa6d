<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
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
</context>
<context>
    <name>thespis::studio::MainWindow</name>
    <message>
        <source>No scenario is open.
Use File ▸ Open… (Ctrl+O) to open a .thespis file.</source>
        <translation>Kein Szenario geöffnet.
Öffnen Sie mit Datei ▸ Öffnen… (Strg+O) eine .thespis-Datei.</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>&amp;Öffnen…</translation>
    </message>
    <message>
        <source>Open a scenario file (.thespis)</source>
        <translation>Eine Szenariodatei (.thespis) öffnen</translation>
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
    <message>
        <source>This scenario has no characters yet.</source>
        <translation>Dieses Szenario hat noch keine Figuren.</translation>
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
    <message numerus="yes">
        <source>%n warning(s), see the terminal.</source>
        <translation>
            <numerusform>%n Warnung, siehe Terminal.</numerusform>
            <numerusform>%n Warnungen, siehe Terminal.</numerusform>
        </translation>
    </message>
    <message>
        <source>Open Scenario</source>
        <translation>Szenario öffnen</translation>
    </message>
    <message>
        <source>Thespis scenarios (*.thespis);;All files (*)</source>
        <translation>Thespis-Szenarien (*.thespis);;Alle Dateien (*)</translation>
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
        <translation>Einheiten</translation>
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
</context>
</TS>

<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en_US">
<context>
    <name>thespis::editor::ArCalibrationDialog</name>
    <message numerus="yes">
        <source>%n view(s) so far</source>
        <translation>
            <numerusform>%n view so far</numerusform>
            <numerusform>%n views so far</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Calibrating from %n view(s)…</source>
        <translation>
            <numerusform>Calibrating from %n view…</numerusform>
            <numerusform>Calibrating from %n views…</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>thespis::editor::ArPreviewPanel</name>
    <message numerus="yes">
        <source>Tracking: %n feature(s)</source>
        <translation>
            <numerusform>Tracking: %n feature</numerusform>
            <numerusform>Tracking: %n features</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>thespis::editor::CharacterDialog</name>
    <message numerus="yes">
        <source>Import its %n animation(s) as clips</source>
        <translation>
            <numerusform>Import its %n animation as a clip</numerusform>
            <numerusform>Import its %n animations as clips</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>thespis::editor::CharacterProperties</name>
    <message numerus="yes">
        <source>%n layer(s)</source>
        <translation>
            <numerusform>%n layer</numerusform>
            <numerusform>%n layers</numerusform>
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
</context>
<context>
    <name>thespis::editor::ContentActions</name>
    <message numerus="yes">
        <source>Import %n Clip(s)</source>
        <translation>
            <numerusform>Import %n Clip</numerusform>
            <numerusform>Import %n Clips</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>thespis::editor::ConversationPanel</name>
    <message numerus="yes">
        <source>%1 and %n more</source>
        <translation>
            <numerusform>%1 and %n more</numerusform>
            <numerusform>%1 and %n more</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n word(s) not in the dictionary, pronounced by espeak-ng.</source>
        <translation>
            <numerusform>%n word not in the dictionary, pronounced by espeak-ng.</numerusform>
            <numerusform>%n words not in the dictionary, pronounced by espeak-ng.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>“%1”: %n categories</source>
        <translation>
            <numerusform>“%1”: %n category</numerusform>
            <numerusform>“%1”: %n categories</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>, %n set(s)</source>
        <translation>
            <numerusform>, %n set</numerusform>
            <numerusform>, %n sets</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>, %n map(s)</source>
        <translation>
            <numerusform>, %n map</numerusform>
            <numerusform>, %n maps</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n pattern(s) to listen for</source>
        <translation>
            <numerusform>%n pattern to listen for</numerusform>
            <numerusform>%n patterns to listen for</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source> (%n left out)</source>
        <translation>
            <numerusform> (%n left out)</numerusform>
            <numerusform> (%n left out)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>, %n word(s); wildcards stand for %1 of them.</source>
        <translation>
            <numerusform>, %n word; wildcards stand for %1 of them.</numerusform>
            <numerusform>, %n words; wildcards stand for %1 of them.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Loaded %n categories in %1 s.</source>
        <translation>
            <numerusform>Loaded %n category in %1 s.</numerusform>
            <numerusform>Loaded %n categories in %1 s.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n problem(s) in its files: the rest loaded.</source>
        <translation>
            <numerusform>%n problem in its files: the rest loaded.</numerusform>
            <numerusform>%n problems in its files: the rest loaded.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Bot “%1” loaded: %n categories.</source>
        <translation>
            <numerusform>Bot “%1” loaded: %n category.</numerusform>
            <numerusform>Bot “%1” loaded: %n categories.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>thespis::editor::CurvePanel</name>
    <message numerus="yes">
        <source>Move %n Curve Key(s)</source>
        <translation>
            <numerusform>Move %n Curve Key</numerusform>
            <numerusform>Move %n Curve Keys</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>thespis::editor::ExportMotionDialog</name>
    <message numerus="yes">
        <source>Wrote %1: %n frame(s) at %2 fps.</source>
        <translation>
            <numerusform>Wrote %1: %n frame at %2 fps.</numerusform>
            <numerusform>Wrote %1: %n frames at %2 fps.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>thespis::editor::ExportPackageDialog</name>
    <message numerus="yes">
        <source>The scenario and %n file(s), %1 before compression.</source>
        <translation>
            <numerusform>The scenario and %n file, %1 before compression.</numerusform>
            <numerusform>The scenario and %n files, %1 before compression.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>thespis::editor::GesticonPanel</name>
    <message numerus="yes">
        <source>Remove %n Gesture(s)</source>
        <translation>
            <numerusform>Remove %n Gesture</numerusform>
            <numerusform>Remove %n Gestures</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>thespis::editor::ImportMotionDialog</name>
    <message numerus="yes">
        <source>%1, %n frame(s) at %2 fps</source>
        <translation>
            <numerusform>%1, %n frame at %2 fps</numerusform>
            <numerusform>%1, %n frames at %2 fps</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>&lt;b&gt;%1&lt;/b&gt;: %2, %n frame(s) at %3 fps.</source>
        <translation>
            <numerusform>&lt;b&gt;%1&lt;/b&gt;: %2, %n frame at %3 fps.</numerusform>
            <numerusform>&lt;b&gt;%1&lt;/b&gt;: %2, %n frames at %3 fps.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Joint names: %1; it moves %n of the character&apos;s joints.</source>
        <translation>
            <numerusform>Joint names: %1; it moves %n of the character&apos;s joints.</numerusform>
            <numerusform>Joint names: %1; it moves %n of the character&apos;s joints.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n more</source>
        <translation>
            <numerusform>%n more</numerusform>
            <numerusform>%n more</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Joint mapping of %1 (%n joint(s)):</source>
        <translation>
            <numerusform>Joint mapping of %1 (%n joint):</numerusform>
            <numerusform>Joint mapping of %1 (%n joints):</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Import %n Clip(s)</source>
        <translation>
            <numerusform>Import %n Clip</numerusform>
            <numerusform>Import %n Clips</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n joint(s) have no H-Anim name and keep their own: %1.</source>
        <translation>
            <numerusform>%n joint has no H-Anim name and keeps its own: %1.</numerusform>
            <numerusform>%n joints have no H-Anim name and keep their own: %1.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Of these, %n move(s) nothing of this character (neither they nor a joint below them is in its skeleton): %1.</source>
        <translation>
            <numerusform>Of these, %n moves nothing of this character (neither it nor a joint below it is in its skeleton): %1.</numerusform>
            <numerusform>Of these, %n move nothing of this character (neither they nor a joint below them is in its skeleton): %1.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>thespis::editor::PropertiesPanel</name>
    <message numerus="yes">
        <source>%n character(s)</source>
        <translation>
            <numerusform>%n character</numerusform>
            <numerusform>%n characters</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n action(s)</source>
        <translation>
            <numerusform>%n action</numerusform>
            <numerusform>%n actions</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>keyframed weight curve (%n key(s))</source>
        <translation>
            <numerusform>keyframed weight curve (%n key)</numerusform>
            <numerusform>keyframed weight curve (%n keys)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>thespis::editor::ScenarioTreeModel</name>
    <message numerus="yes">
        <source>loop %n time(s)</source>
        <translation>
            <numerusform>loop %n time</numerusform>
            <numerusform>loop %n times</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>keyframed, %n key(s)</source>
        <translation>
            <numerusform>keyframed, %n key</numerusform>
            <numerusform>keyframed, %n keys</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n clip(s)</source>
        <translation>
            <numerusform>%n clip</numerusform>
            <numerusform>%n clips</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>thespis::editor::SegmentTableModel</name>
    <message numerus="yes">
        <source>Tag %n Segment(s)</source>
        <translation>
            <numerusform>Tag %n Segment</numerusform>
            <numerusform>Tag %n Segments</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>thespis::editor::SpeechPanel</name>
    <message numerus="yes">
        <source>Previewing %1 s of speech from %2 s: %n viseme(s)</source>
        <translation>
            <numerusform>Previewing %1 s of speech from %2 s: %n viseme</numerusform>
            <numerusform>Previewing %1 s of speech from %2 s: %n visemes</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Inserted at %1 s: %n viseme(s), %2 face and %3 body gesture(s).</source>
        <translation>
            <numerusform>Inserted at %1 s: %n viseme, %2 face and %3 body gesture(s).</numerusform>
            <numerusform>Inserted at %1 s: %n visemes, %2 face and %3 body gesture(s).</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Lip-synced “%1”: %n word(s), %2 viseme(s).</source>
        <translation>
            <numerusform>Lip-synced “%1”: %n word, %2 viseme(s).</numerusform>
            <numerusform>Lip-synced “%1”: %n words, %2 viseme(s).</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Previewing BML block “%1” from %2 s to %3 s: %n behaviour(s)</source>
        <translation>
            <numerusform>Previewing BML block “%1” from %2 s to %3 s: %n behaviour</numerusform>
            <numerusform>Previewing BML block “%1” from %2 s to %3 s: %n behaviours</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Inserted BML from %1 s to %2 s: %n speech(es), %3 gesture(s), %4 head gesture(s), %5 face lexeme(s), %6 gaze(s).</source>
        <translation>
            <numerusform>Inserted BML from %1 s to %2 s: %n speech, %3 gesture(s), %4 head gesture(s), %5 face lexeme(s), %6 gaze(s).</numerusform>
            <numerusform>Inserted BML from %1 s to %2 s: %n speeches, %3 gesture(s), %4 head gesture(s), %5 face lexeme(s), %6 gaze(s).</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>thespis::editor::TimelinePanel</name>
    <message numerus="yes">
        <source>Move %n Action(s)</source>
        <translation>
            <numerusform>Move %n Action</numerusform>
            <numerusform>Move %n Actions</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Ripple Delete %n Action(s)</source>
        <translation>
            <numerusform>Ripple Delete %n Action</numerusform>
            <numerusform>Ripple Delete %n Actions</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Delete %n Action(s)</source>
        <translation>
            <numerusform>Delete %n Action</numerusform>
            <numerusform>Delete %n Actions</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Paste %n Action(s)</source>
        <translation>
            <numerusform>Paste %n Action</numerusform>
            <numerusform>Paste %n Actions</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Duplicate %n Action(s)</source>
        <translation>
            <numerusform>Duplicate %n Action</numerusform>
            <numerusform>Duplicate %n Actions</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>thespis::studio::MainWindow</name>
    <message numerus="yes">
        <source>Opened %1: %n character(s)</source>
        <translation>
            <numerusform>Opened %1: %n character</numerusform>
            <numerusform>Opened %1: %n characters</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>, %n action(s)</source>
        <translation>
            <numerusform>, %n action</numerusform>
            <numerusform>, %n actions</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n warning(s): see Messages.</source>
        <translation>
            <numerusform>%n warning: see Messages.</numerusform>
            <numerusform>%n warnings: see Messages.</numerusform>
        </translation>
    </message>
</context>
</TS>

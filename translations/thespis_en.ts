<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en_US">
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
        <source>%n warning(s), see the terminal.</source>
        <translation>
            <numerusform>%n warning, see the terminal.</numerusform>
            <numerusform>%n warnings, see the terminal.</numerusform>
        </translation>
    </message>
</context>
</TS>

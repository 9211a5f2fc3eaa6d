<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en_US">
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

<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en">
<context>
    <name>MainWindow</name>
    <message numerus="yes">
        <location filename="../../widgets/main_window.py" line="690"/>
        <source>rejected frames: %n</source>
        <translation>
            <numerusform>rejected frames: %n</numerusform>
            <numerusform>rejected frames: %n</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/main_window.py" line="725"/>
        <source>%n settings could not be used; defaults are used instead</source>
        <translation>
            <numerusform>%n setting could not be used; the default is used instead</numerusform>
            <numerusform>%n settings could not be used; defaults are used instead</numerusform>
        </translation>
    </message>
</context>
</TS>

<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="cs">
<context>
    <name>MainWindow</name>
    <message>
        <location filename="../../widgets/main_window.py" line="94"/>
        <source>Jog X while held</source>
        <extracomment>Widgets in which arrow keys move a text cursor or step a value, so they must not jog. Keys and what they do (translated where shown: QT_TRANSLATE_NOOP only marks them).</extracomment>
        <translation>Posuv v ose X, dokud je klávesa stisknutá</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="95"/>
        <source>Jog Y while held (two arrows at once = diagonal)</source>
        <translation>Posuv v ose Y, dokud je klávesa stisknutá (dvě šipky naráz = šikmo)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="98"/>
        <source>Jog Z while held, on machines with a Z axis</source>
        <translation>Posuv v ose Z, dokud je klávesa stisknutá (stroje s osou Z)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="100"/>
        <source>Jog and move at the other speed</source>
        <translation>Posuv a pohyb druhou rychlostí</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="101"/>
        <source>Stop everything, from anywhere in the window</source>
        <translation>Zastavit vše, odkudkoli v okně</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="104"/>
        <source>Manual / Absolute / Relative / Dynamics / Link / Axes / G-code page</source>
        <translation>Stránka Manuální / Absolutně / Relativně / Dynamika / Spojení / Osy / G-kód</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="108"/>
        <source>Open a job (File → Open job…)</source>
        <translation>Otevřít úlohu (Soubor → Otevřít úlohu…)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="109"/>
        <source>Quit (stops the machine first)</source>
        <translation>Ukončit (nejprve zastaví stroj)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="110"/>
        <source>Show or hide the jobs dock</source>
        <translation>Zobrazit nebo skrýt panel úloh</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="111"/>
        <source>Show or hide the telemetry plots</source>
        <translation>Zobrazit nebo skrýt grafy telemetrie</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="112"/>
        <source>Show or hide the developer pane</source>
        <translation>Zobrazit nebo skrýt vývojářský panel</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="113"/>
        <source>This list</source>
        <translation>Tento přehled</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="187"/>
        <source>StepDeck — {0}</source>
        <extracomment>The operator chose another machine profile; the launcher rebuilds station and window. The box listing settings the station could not use (None: there were none).</extracomment>
        <translation>StepDeck — {0}</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="202"/>
        <source>&amp;Manual</source>
        <translation>&amp;Manuální</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="202"/>
        <source>Hold-to-jog buttons, Home (Alt+M)</source>
        <translation>Tlačítka posuvu (držet), reference (Alt+M)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="212"/>
        <source>D&amp;rill</source>
        <extracomment>Every page with motion controls, for the motion lock.</extracomment>
        <translation>V&amp;rtačka</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="214"/>
        <source>Command buttons, X/Y, terminal (Alt+R)</source>
        <translation>Tlačítka příkazů, X/Y, terminál (Alt+R)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="220"/>
        <source>A&amp;xes</source>
        <translation>Osy (&amp;X)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="220"/>
        <source>Move by mm, step size, thread (Alt+X)</source>
        <translation>Posun o mm, mikrokrok, stoupání závitu (Alt+X)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="227"/>
        <source>&amp;Absolute</source>
        <translation>&amp;Absolutně</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="227"/>
        <source>Move to a target (Alt+A)</source>
        <translation>Najet na zadanou polohu (Alt+A)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="230"/>
        <source>&amp;Relative</source>
        <translation>&amp;Relativně</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="230"/>
        <source>Move by an increment (Alt+R)</source>
        <translation>Posunout o přírůstek (Alt+R)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="236"/>
        <source>&amp;G-code</source>
        <translation>&amp;G-kód</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="238"/>
        <source>Console, pen, hold/resume/reset (Alt+G)</source>
        <translation>Konzole, pero, pozastavení/pokračování/reset (Alt+G)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="249"/>
        <source>&amp;Dynamics</source>
        <translation>&amp;Dynamika</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="249"/>
        <source>Device parameters (Alt+D)</source>
        <translation>Parametry zařízení (Alt+D)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="254"/>
        <source>&amp;Link</source>
        <translation>Spojení (&amp;L)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="256"/>
        <source>Connect: emulator, serial port or BLE (Alt+L)</source>
        <translation>Připojení: emulátor, sériový port nebo BLE (Alt+L)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="338"/>
        <source>&amp;Colours</source>
        <translation>&amp;Barvy</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="342"/>
        <location filename="../../widgets/main_window.py" line="358"/>
        <source>As the &amp;system</source>
        <translation>Podle &amp;systému</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="343"/>
        <source>&amp;Light</source>
        <translation>&amp;Světlé</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="344"/>
        <source>&amp;Dark</source>
        <translation>&amp;Tmavé</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="355"/>
        <source>L&amp;anguage</source>
        <translation>&amp;Jazyk</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="374"/>
        <source>The language changes when StepDeck starts again</source>
        <translation>Jazyk se změní při příštím spuštění StepDecku</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="392"/>
        <source>Frames from the device that failed to decode</source>
        <translation>Rámce ze zařízení, které nešlo dekódovat</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="406"/>
        <source>&amp;File</source>
        <translation>&amp;Soubor</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="407"/>
        <source>&amp;Open job…</source>
        <translation>&amp;Otevřít úlohu…</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="411"/>
        <source>&amp;Recent jobs</source>
        <translation>&amp;Nedávné úlohy</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="415"/>
        <source>&amp;Quit</source>
        <translation>&amp;Ukončit</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="420"/>
        <source>&amp;Machine</source>
        <translation>S&amp;troj</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="421"/>
        <source>&amp;Connect</source>
        <translation>&amp;Připojit</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="423"/>
        <source>&amp;Disconnect</source>
        <translation>&amp;Odpojit</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="437"/>
        <source>&amp;Stop</source>
        <translation>&amp;Zastavit</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="437"/>
        <source>&amp;Drop the queue</source>
        <translation>&amp;Zahodit frontu příkazů</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="445"/>
        <source>&amp;View</source>
        <translation>&amp;Zobrazení</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="446"/>
        <source>&amp;Help</source>
        <translation>&amp;Nápověda</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="447"/>
        <source>&amp;Keys</source>
        <translation>&amp;Klávesy</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="452"/>
        <source>&amp;About StepDeck</source>
        <translation>&amp;O programu StepDeck</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="488"/>
        <source>(none yet)</source>
        <translation>(zatím žádné)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="491"/>
        <source>&amp;Clear the list</source>
        <translation>&amp;Vymazat seznam</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="518"/>
        <source>A control station for small stepper machines: XY stages, a PCB drill, G-code plotters, the usb3 unit and the string-art winder.</source>
        <translation>Řídicí stanice pro malé stroje s krokovými motory: XY stolky, vrtačku plošných spojů, plotry na G-kód, jednotku usb3 a navíječku pro string art.</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="521"/>
        <source>Machine: {0}</source>
        <translation>Stroj: {0}</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="524"/>
        <source>About StepDeck</source>
        <translation>O programu StepDeck</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="545"/>
        <source>Arrows do not jog while a text or number field has focus: there they keep editing. Esc works from anywhere in the window and also closes an open menu; in a dialog (like this one) Esc closes the dialog only.</source>
        <translation>Když je aktivní textové nebo číselné pole, šipky strojem nepohybují, ale upravují text. Esc funguje odkudkoli v okně a zavře i otevřenou nabídku; v dialogu (jako je tento) Esc jen zavře dialog.</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="553"/>
        <source>StepDeck — keyboard shortcuts</source>
        <translation>StepDeck — klávesové zkratky</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="669"/>
        <source>Motion locked: {0}</source>
        <translation>Pohyb zablokován: {0}</translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/main_window.py" line="690"/>
        <source>rejected frames: %n</source>
        <translation>
            <numerusform>%n odmítnutý rámec</numerusform>
            <numerusform>%n odmítnuté rámce</numerusform>
            <numerusform>%n odmítnutých rámců</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/main_window.py" line="725"/>
        <source>%n settings could not be used; defaults are used instead</source>
        <translation>
            <numerusform>%n nastavení nešlo použít; platí výchozí hodnota</numerusform>
            <numerusform>%n nastavení nešlo použít; platí výchozí hodnoty</numerusform>
            <numerusform>%n nastavení nešlo použít; platí výchozí hodnoty</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="730"/>
        <source>StepDeck — settings</source>
        <translation>StepDeck — nastavení</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="772"/>
        <source>Stopping every axis before closing…</source>
        <translation>Před zavřením zastavuji všechny osy…</translation>
    </message>
</context>
</TS>

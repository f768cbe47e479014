<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="sk">
<context>
    <name>MainWindow</name>
    <message>
        <location filename="../../widgets/main_window.py" line="94"/>
        <source>Jog X while held</source>
        <extracomment>Widgets in which arrow keys move a text cursor or step a value, so they must not jog. Keys and what they do (translated where shown: QT_TRANSLATE_NOOP only marks them).</extracomment>
        <translation>Posuv v osi X, kým je kláves stlačený</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="95"/>
        <source>Jog Y while held (two arrows at once = diagonal)</source>
        <translation>Posuv v osi Y, kým je kláves stlačený (dve šípky naraz = šikmo)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="98"/>
        <source>Jog Z while held, on machines with a Z axis</source>
        <translation>Posuv v osi Z, kým je kláves stlačený (stroje s osou Z)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="100"/>
        <source>Jog and move at the other speed</source>
        <translation>Posuv a pohyb druhou rýchlosťou</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="101"/>
        <source>Stop everything, from anywhere in the window</source>
        <translation>Zastaviť všetko, odkiaľkoľvek v okne</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="104"/>
        <source>Manual / Absolute / Relative / Dynamics / Link / Axes / G-code page</source>
        <translation>Stránka Manuálne / Absolútne / Relatívne / Dynamika / Spojenie / Osi / G-kód</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="108"/>
        <source>Open a job (File → Open job…)</source>
        <translation>Otvoriť úlohu (Súbor → Otvoriť úlohu…)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="109"/>
        <source>Quit (stops the machine first)</source>
        <translation>Ukončiť (najprv zastaví stroj)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="110"/>
        <source>Show or hide the jobs dock</source>
        <translation>Zobraziť alebo skryť panel úloh</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="111"/>
        <source>Show or hide the telemetry plots</source>
        <translation>Zobraziť alebo skryť grafy telemetrie</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="112"/>
        <source>Show or hide the developer pane</source>
        <translation>Zobraziť alebo skryť vývojársky panel</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="113"/>
        <source>This list</source>
        <translation>Tento prehľad</translation>
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
        <translation>&amp;Manuálne</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="202"/>
        <source>Hold-to-jog buttons, Home (Alt+M)</source>
        <translation>Tlačidlá posuvu (držať), referencia (Alt+M)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="212"/>
        <source>D&amp;rill</source>
        <extracomment>Every page with motion controls, for the motion lock.</extracomment>
        <translation>V&amp;ŕtačka</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="214"/>
        <source>Command buttons, X/Y, terminal (Alt+R)</source>
        <translation>Tlačidlá príkazov, X/Y, terminál (Alt+R)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="220"/>
        <source>A&amp;xes</source>
        <translation>Osi (&amp;X)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="220"/>
        <source>Move by mm, step size, thread (Alt+X)</source>
        <translation>Posun o mm, mikrokrok, stúpanie závitu (Alt+X)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="227"/>
        <source>&amp;Absolute</source>
        <translation>&amp;Absolútne</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="227"/>
        <source>Move to a target (Alt+A)</source>
        <translation>Nabehnúť na zadanú polohu (Alt+A)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="230"/>
        <source>&amp;Relative</source>
        <translation>&amp;Relatívne</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="230"/>
        <source>Move by an increment (Alt+R)</source>
        <translation>Posunúť o prírastok (Alt+R)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="236"/>
        <source>&amp;G-code</source>
        <translation>&amp;G-kód</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="238"/>
        <source>Console, pen, hold/resume/reset (Alt+G)</source>
        <translation>Konzola, pero, pozastavenie/pokračovanie/reset (Alt+G)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="249"/>
        <source>&amp;Dynamics</source>
        <translation>&amp;Dynamika</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="249"/>
        <source>Device parameters (Alt+D)</source>
        <translation>Parametre zariadenia (Alt+D)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="254"/>
        <source>&amp;Link</source>
        <translation>Spojenie (&amp;L)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="256"/>
        <source>Connect: emulator, serial port or BLE (Alt+L)</source>
        <translation>Pripojenie: emulátor, sériový port alebo BLE (Alt+L)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="338"/>
        <source>&amp;Colours</source>
        <translation>&amp;Farby</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="342"/>
        <location filename="../../widgets/main_window.py" line="358"/>
        <source>As the &amp;system</source>
        <translation>Podľa &amp;systému</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="343"/>
        <source>&amp;Light</source>
        <translation>&amp;Svetlé</translation>
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
        <translation>Jazyk sa zmení pri ďalšom spustení StepDecku</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="392"/>
        <source>Frames from the device that failed to decode</source>
        <translation>Rámce zo zariadenia, ktoré sa nepodarilo dekódovať</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="406"/>
        <source>&amp;File</source>
        <translation>&amp;Súbor</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="407"/>
        <source>&amp;Open job…</source>
        <translation>&amp;Otvoriť úlohu…</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="411"/>
        <source>&amp;Recent jobs</source>
        <translation>&amp;Nedávne úlohy</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="415"/>
        <source>&amp;Quit</source>
        <translation>&amp;Ukončiť</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="420"/>
        <source>&amp;Machine</source>
        <translation>S&amp;troj</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="421"/>
        <source>&amp;Connect</source>
        <translation>&amp;Pripojiť</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="423"/>
        <source>&amp;Disconnect</source>
        <translation>&amp;Odpojiť</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="437"/>
        <source>&amp;Stop</source>
        <translation>&amp;Zastaviť</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="437"/>
        <source>&amp;Drop the queue</source>
        <translation>&amp;Zahodiť frontu príkazov</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="445"/>
        <source>&amp;View</source>
        <translation>&amp;Zobrazenie</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="446"/>
        <source>&amp;Help</source>
        <translation>&amp;Pomocník</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="447"/>
        <source>&amp;Keys</source>
        <translation>&amp;Klávesy</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="452"/>
        <source>&amp;About StepDeck</source>
        <translation>&amp;O programe StepDeck</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="488"/>
        <source>(none yet)</source>
        <translation>(zatiaľ žiadne)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="491"/>
        <source>&amp;Clear the list</source>
        <translation>&amp;Vymazať zoznam</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="518"/>
        <source>A control station for small stepper machines: XY stages, a PCB drill, G-code plotters, the usb3 unit and the string-art winder.</source>
        <translation>Riadiaca stanica pre malé stroje s krokovými motormi: XY stolíky, vŕtačku plošných spojov, plotre na G-kód, jednotku usb3 a navíjačku pre string art.</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="521"/>
        <source>Machine: {0}</source>
        <translation>Stroj: {0}</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="524"/>
        <source>About StepDeck</source>
        <translation>O programe StepDeck</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="545"/>
        <source>Arrows do not jog while a text or number field has focus: there they keep editing. Esc works from anywhere in the window and also closes an open menu; in a dialog (like this one) Esc closes the dialog only.</source>
        <translation>Keď je aktívne textové alebo číselné pole, šípky strojom nepohybujú, ale upravujú text. Esc funguje odkiaľkoľvek v okne a zavrie aj otvorenú ponuku; v dialógu (ako je tento) Esc iba zavrie dialóg.</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="553"/>
        <source>StepDeck — keyboard shortcuts</source>
        <translation>StepDeck — klávesové skratky</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="669"/>
        <source>Motion locked: {0}</source>
        <translation>Pohyb zablokovaný: {0}</translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/main_window.py" line="690"/>
        <source>rejected frames: %n</source>
        <translation>
            <numerusform>%n odmietnutý rámec</numerusform>
            <numerusform>%n odmietnuté rámce</numerusform>
            <numerusform>%n odmietnutých rámcov</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/main_window.py" line="725"/>
        <source>%n settings could not be used; defaults are used instead</source>
        <translation>
            <numerusform>%n nastavenie sa nedalo použiť; platí predvolená hodnota</numerusform>
            <numerusform>%n nastavenia sa nedali použiť; platia predvolené hodnoty</numerusform>
            <numerusform>%n nastavení sa nedalo použiť; platia predvolené hodnoty</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="730"/>
        <source>StepDeck — settings</source>
        <translation>StepDeck — nastavenia</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.py" line="772"/>
        <source>Stopping every axis before closing…</source>
        <translation>Pred zatvorením zastavujem všetky osi…</translation>
    </message>
</context>
</TS>

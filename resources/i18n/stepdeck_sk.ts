<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="sk">
<context>
    <name>AbsolutePanel</name>
    <message>
        <source>Move to</source>
        <translation>Presunúť na</translation>
    </message>
    <message>
        <source>{0} target, 0…{1} {2} (Esc stops)</source>
        <translation>Cieľová poloha {0}, 0…{1} {2} (Esc zastaví)</translation>
    </message>
    <message>
        <source>Go {0}</source>
        <translation>Ísť {0}</translation>
    </message>
    <message>
        <source>Move {0} to the target</source>
        <translation>Presunúť os {0} na cieľovú polohu</translation>
    </message>
    <message>
        <source>{0} target</source>
        <translation>Cieľ {0}</translation>
    </message>
    <message>
        <source>Go all</source>
        <translation>Ísť so všetkými</translation>
    </message>
    <message>
        <source>Move every axis to its target at once</source>
        <translation>Presunúť všetky osi naraz na ich cieľové polohy</translation>
    </message>
</context>
<context>
    <name>AxisStatus</name>
    <message>
        <source>unknown</source>
        <extracomment>Every axis status a session reports (the stage&apos;s, the drill&apos;s, usb3&apos;s and GRBL&apos;s).</extracomment>
        <translation>neznámy</translation>
    </message>
    <message>
        <source>idle</source>
        <translation>v pokoji</translation>
    </message>
    <message>
        <source>moving</source>
        <translation>v pohybe</translation>
    </message>
    <message>
        <source>parking</source>
        <translation>parkuje</translation>
    </message>
    <message>
        <source>parked</source>
        <translation>zaparkované</translation>
    </message>
    <message>
        <source>accelerating</source>
        <translation>zrýchľuje</translation>
    </message>
    <message>
        <source>constant speed</source>
        <translation>konštantná rýchlosť</translation>
    </message>
    <message>
        <source>decelerating</source>
        <translation>brzdí</translation>
    </message>
    <message>
        <source>target reached</source>
        <translation>v cieli</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>zastavené</translation>
    </message>
    <message>
        <source>homing</source>
        <translation>referenčný posuv</translation>
    </message>
    <message>
        <source>end switch hit</source>
        <translation>narazil na koncový spínač</translation>
    </message>
    <message>
        <source>blocked: battery low</source>
        <translation>blokované: slabá batéria</translation>
    </message>
    <message>
        <source>blocked: charger connected</source>
        <translation>blokované: pripojená nabíjačka</translation>
    </message>
    <message>
        <source>blocked: USB connected</source>
        <translation>blokované: pripojené USB</translation>
    </message>
    <message>
        <source>sleeping</source>
        <translation>spí</translation>
    </message>
    <message>
        <source>driver fault</source>
        <translation>porucha budiča</translation>
    </message>
    <message>
        <source>parameter rejected</source>
        <translation>parameter odmietnutý</translation>
    </message>
    <message>
        <source>unknown command</source>
        <translation>neznámy príkaz</translation>
    </message>
    <message>
        <source>run</source>
        <translation>beží</translation>
    </message>
    <message>
        <source>hold</source>
        <translation>pozastavené</translation>
    </message>
    <message>
        <source>jog</source>
        <translation>ručný posuv</translation>
    </message>
    <message>
        <source>alarm</source>
        <translation>alarm</translation>
    </message>
    <message>
        <source>door</source>
        <translation>dvierka otvorené</translation>
    </message>
    <message>
        <source>check</source>
        <translation>kontrolný režim</translation>
    </message>
    <message>
        <source>home</source>
        <translation>referenčný posuv</translation>
    </message>
    <message>
        <source>sleep</source>
        <translation>spánok</translation>
    </message>
</context>
<context>
    <name>BoardDialog</name>
    <message>
        <source>String-art board</source>
        <translation>Doska pre string art</translation>
    </message>
    <message numerus="yes">
        <source>&lt;b&gt;{0}&lt;/b&gt; lists %n nail visit(s) without a param.txt. Which board is it for?</source>
        <translation>
            <numerusform>&lt;b&gt;{0}&lt;/b&gt; obsahuje %n návštevu klinca bez súboru param.txt. Pre akú dosku je?</numerusform>
            <numerusform>&lt;b&gt;{0}&lt;/b&gt; obsahuje %n návštevy klincov bez súboru param.txt. Pre akú dosku je?</numerusform>
            <numerusform>&lt;b&gt;{0}&lt;/b&gt; obsahuje %n návštev klincov bez súboru param.txt. Pre akú dosku je?</numerusform>
        </translation>
    </message>
    <message>
        <source>circle</source>
        <translation>kruh</translation>
    </message>
    <message>
        <source>{0}-gon</source>
        <translation>{0}-uholník</translation>
    </message>
    <message>
        <source>At least {0}: the list names nail {1}</source>
        <translation>Najmenej {0}: zoznam uvádza klinec {1}</translation>
    </message>
    <message>
        <source>Board radius; the nails sit 1.5 cm inside its edge</source>
        <translation>Polomer dosky; klince sú 1,5 cm od jej okraja</translation>
    </message>
    <message>
        <source>Shape</source>
        <translation>Tvar</translation>
    </message>
    <message>
        <source>Nails</source>
        <translation>Klince</translation>
    </message>
    <message>
        <source>Board radius</source>
        <translation>Polomer dosky</translation>
    </message>
</context>
<context>
    <name>ConnectionPanel</name>
    <message>
        <source>Built-in emulator</source>
        <translation>Vstavaný emulátor</translation>
    </message>
    <message>
        <source>Serial port</source>
        <translation>Sériový port</translation>
    </message>
    <message>
        <source>Bluetooth LE</source>
        <translation>Bluetooth LE</translation>
    </message>
    <message>
        <source>Switching machine closes this link and opens the new one</source>
        <extracomment>The link is remembered per machine: the drill&apos;s port is not the stage&apos;s.</extracomment>
        <translation>Prepnutím stroja sa toto spojenie ukončí a otvorí sa nové</translation>
    </message>
    <message>
        <source>Refresh</source>
        <translation>Obnoviť</translation>
    </message>
    <message>
        <source>Serial</source>
        <translation>Sériová linka</translation>
    </message>
    <message>
        <source>Port</source>
        <translation>Port</translation>
    </message>
    <message>
        <source>Baud rate</source>
        <translation>Prenosová rýchlosť</translation>
    </message>
    <message>
        <source>Scan</source>
        <translation>Hľadať</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>Pripojiť</translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation>Odpojiť</translation>
    </message>
    <message>
        <source>Stop every axis, wait briefly for the machine to confirm, then close the link</source>
        <translation>Zastaví všetky osi, krátko počká na potvrdenie stroja a potom ukončí spojenie</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Stroj</translation>
    </message>
    <message>
        <source>Link</source>
        <translation>Spojenie</translation>
    </message>
    <message>
        <source>(no name)</source>
        <translation>(bez názvu)</translation>
    </message>
    <message>
        <source>Scanning…</source>
        <translation>Hľadám…</translation>
    </message>
    <message numerus="yes">
        <source>%n found</source>
        <translation>
            <numerusform>nájdené %n zariadenie</numerusform>
            <numerusform>nájdené %n zariadenia</numerusform>
            <numerusform>nájdených %n zariadení</numerusform>
        </translation>
    </message>
    <message>
        <source>No stage found</source>
        <translation>Nenašiel sa žiadny stolík</translation>
    </message>
    <message>
        <source>Choose a serial port first (Refresh lists them).</source>
        <translation>Najprv vyberte sériový port (Obnoviť ich vypíše).</translation>
    </message>
</context>
<context>
    <name>ConsoleGate</name>
    <message>
        <source>{0} would move {1}</source>
        <extracomment>GRBL&apos;s &quot;setting disabled&quot;: for ``$H`` it means homing is off (``$22=0``, a new board&apos;s). Whether the board is in G91 after the lines queued (a reset brings back G90).</extracomment>
        <translation>{0} by pohol {1}</translation>
    </message>
    <message>
        <source>. Homing is switched off on the board ($22=0, GRBL&apos;s default): with end switches fitted, send $22=1 from the console; without them, move the machine to its origin by hand and set it there</source>
        <translation>. Referenčná jazda je na doske vypnutá ($22=0, predvolená v GRBL): s koncovými spínačmi pošlite z konzoly $22=1; bez nich presuňte stroj do počiatku ručne a nastavte ho tam</translation>
    </message>
</context>
<context>
    <name>DeveloperPane</name>
    <message>
        <source>Developer</source>
        <translation>Vývojár</translation>
    </message>
    <message>
        <source>Simulation: the built-in emulator answers the commands</source>
        <translation>Simulácia: na príkazy odpovedá vstavaný emulátor</translation>
    </message>
    <message>
        <source>On: connect the emulated stage (when no device is connected). Off: disconnect it.</source>
        <translation>Zapnuté: pripojí emulovaný stolík (ak nie je pripojené žiadne zariadenie). Vypnuté: odpojí ho.</translation>
    </message>
    <message>
        <source>Simulation refused: {0}</source>
        <translation>Simulácia odmietnutá: {0}</translation>
    </message>
</context>
<context>
    <name>DrillConversionBox</name>
    <message>
        <source>Conversion constants (teaching)</source>
        <translation>Prevodové konštanty (výučba)</translation>
    </message>
    <message>
        <source>Excellon step, 1/… inch</source>
        <translation>Krok Excellon, 1/… palca</translation>
    </message>
    <message>
        <source>Excellon step</source>
        <translation>Krok Excellon</translation>
    </message>
    <message>
        <source>Excellon step 1/… inch</source>
        <translation>Krok Excellon 1/… palca</translation>
    </message>
    <message>
        <source>{0} microsteps a mm</source>
        <translation>{0} mikrokrokov na mm</translation>
    </message>
    <message>
        <source>Teaching only: with other values than the profile&apos;s the drill goes where these send it, not where the file means (the travel is still checked).</source>
        <translation>Len na výučbu: s inými hodnotami než v profile ide vŕtačka tam, kam ju pošlú tieto, nie kam myslí súbor (rozsah pojazdu sa stále kontroluje).</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Použiť</translation>
    </message>
    <message>
        <source>Read the loaded job again with these constants</source>
        <translation>Načítať úlohu znova s týmito konštantami</translation>
    </message>
    <message>
        <source>Profile values</source>
        <translation>Hodnoty profilu</translation>
    </message>
    <message>
        <source>Back to the machine profile&apos;s constants</source>
        <translation>Späť na konštanty profilu stroja</translation>
    </message>
    <message>
        <source>Not changed: {0}</source>
        <translation>Nezmenené: {0}</translation>
    </message>
</context>
<context>
    <name>DrillDriver</name>
    <message>
        <source>The hole at {0} may or may not have been drilled: the link went before the drill confirmed the command. Look at the board (the hole is marked in the preview), then drill it again or count it as drilled.</source>
        <translation>Otvor na {0} možno je, možno nie je vyvŕtaný: spojenie spadlo skôr, než vŕtačka príkaz potvrdila. Pozrite sa na dosku (otvor je vyznačený v náhľade) a potom ho vyvŕtajte znova, alebo ho započítajte ako vyvŕtaný.</translation>
    </message>
    <message>
        <source>Drill it again</source>
        <translation>Vyvŕtať znova</translation>
    </message>
    <message>
        <source>Count it as drilled</source>
        <translation>Započítať ako vyvŕtaný</translation>
    </message>
    <message>
        <source>the drill ran a command the station did not send ({0}): a hole may have been drilled twice or in the wrong place; look at the board</source>
        <translation>vŕtačka vykonala príkaz, ktorý stanica neposlala ({0}): diera mohla byť vyvŕtaná dvakrát alebo na nesprávnom mieste; skontrolujte dosku</translation>
    </message>
</context>
<context>
    <name>DrillPanel</name>
    <message>
        <source>N  home</source>
        <extracomment>A move expected to run longer than this (seconds) asks first: it cannot be stopped. Buttons of the procedures that take no value: letter, caption, tooltip.</extracomment>
        <translation>N  referencia</translation>
    </message>
    <message>
        <source>Home X then Y to the switches and the zero offsets</source>
        <translation>Referenčný posuv X, potom Y na spínače a nulové posuny</translation>
    </message>
    <message>
        <source>V  drill</source>
        <translation>V  vŕtať</translation>
    </message>
    <message>
        <source>Drill one hole where the head stands</source>
        <translation>Vyvŕtať jeden otvor tam, kde stojí hlava</translation>
    </message>
    <message>
        <source>K  pen down</source>
        <translation>K  pero dole</translation>
    </message>
    <message>
        <source>Lower the pen</source>
        <translation>Spustiť pero</translation>
    </message>
    <message>
        <source>Z  pen up</source>
        <translation>Z  pero hore</translation>
    </message>
    <message>
        <source>Raise the pen</source>
        <translation>Zdvihnúť pero</translation>
    </message>
    <message>
        <source>P  park</source>
        <translation>P  parkovať</translation>
    </message>
    <message>
        <source>Park at the back and switch the motors off</source>
        <translation>Zaparkovať vzadu a vypnúť motory</translation>
    </message>
    <message>
        <source>Commands</source>
        <translation>Príkazy</translation>
    </message>
    <message>
        <source>Timing…</source>
        <translation>Časovanie…</translation>
    </message>
    <message>
        <source>Show the drill&apos;s timing constants, to change them</source>
        <translation>Ukázať časovacie konštanty vŕtačky a zmeniť ich</translation>
    </message>
    <message>
        <source>Step through…</source>
        <translation>Krokovanie…</translation>
    </message>
    <message>
        <source>Walk the loaded job line by line and send its procedures by hand</source>
        <translation>Prejsť načítanú úlohu riadok po riadku a posielať jej procedúry ručne</translation>
    </message>
    <message>
        <source>Constants…</source>
        <translation>Konštanty…</translation>
    </message>
    <message>
        <source>Show the Excellon step and microsteps a mm, to change them</source>
        <translation>Ukázať krok Excellon a mikrokroky na mm, na zmenu</translation>
    </message>
    <message>
        <source>Move to (microsteps from zero)</source>
        <translation>Presunúť na (mikrokroky od nuly)</translation>
    </message>
    <message>
        <source>{0} target; {1} microsteps a mm</source>
        <translation>Cieľ {0}; {1} mikrokrokov na mm</translation>
    </message>
    <message>
        <source>Send {0}</source>
        <translation>Odoslať {0}</translation>
    </message>
    <message>
        <source>{0} target</source>
        <translation>Cieľ {0}</translation>
    </message>
    <message>
        <source>Send anyway</source>
        <translation>Napriek tomu odoslať</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Zrušiť</translation>
    </message>
    <message>
        <source>Terminal</source>
        <translation>Terminál</translation>
    </message>
    <message>
        <source>Send</source>
        <translation>Odoslať</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Vymazať</translation>
    </message>
    <message>
        <source>Clear the terminal and the columns</source>
        <translation>Vymazať terminál a stĺpce</translation>
    </message>
    <message>
        <source>command received</source>
        <translation>príkaz prijatý</translation>
    </message>
    <message>
        <source>command done</source>
        <translation>príkaz vykonaný</translation>
    </message>
    <message>
        <source>! {0}: not sent</source>
        <translation>! {0}: neodoslané</translation>
    </message>
    <message>
        <source>&lt;b&gt;{0}&lt;/b&gt; runs about {1} s, and the drill has no stop command: once it starts, STOP and Esc only drop what is queued after it. Send it?</source>
        <translation>&lt;b&gt;{0}&lt;/b&gt; pobeží asi {1} s a vŕtačka nemá príkaz na zastavenie: keď sa rozbehne, STOP a Esc len zahodia, čo je vo fronte za ním. Odoslať?</translation>
    </message>
    <message>
        <source>   (link check: is the drill there?)</source>
        <extracomment>The device acknowledged the command in flight (``R``); the command&apos;s text. The command in flight has finished (``D``); the command&apos;s text. The device refused the command in flight (``E``); the queue was cleared. The last queued command is done and nothing is waiting. The drill acknowledged or finished what the station did not send, in a way that can harm (a drill cycle run twice, another procedure): the message says what was heard. A line for the terminal: ``&gt; X248`` as sent, ``&lt; RX`` as heard (the text decoded here, so the page only shows it). Station-clock time by which the device must have answered the command in flight. Since when the reply due has been awaited, and from when on it is late. Probes (``I``) written and not yet answered ``EI``. After a silence: until when the drill may still be running the command it had.</extracomment>
        <translation>   (kontrola spojenia: je vŕtačka pripojená?)</translation>
    </message>
    <message>
        <source>  (link check answered: the drill is there)</source>
        <translation>  (kontrola spojenia zodpovedaná: vŕtačka je pripojená)</translation>
    </message>
    <message>
        <source>! {0} refused by the drill; queue cleared</source>
        <translation>! {0} vŕtačka odmietla; front vyprázdnený</translation>
    </message>
</context>
<context>
    <name>DrillSession</name>
    <message>
        <source>The drill has no stop command: {0} queued command(s) dropped; {1} finishes its procedure</source>
        <translation>Vŕtačka nemá príkaz na zastavenie: zahodených príkazov vo fronte: {0}; {1} dokončí svoj postup</translation>
    </message>
    <message>
        <source>The drill has no stop command: {0} queued command(s) dropped</source>
        <translation>Vŕtačka nemá príkaz na zastavenie: zahodených príkazov vo fronte: {0}</translation>
    </message>
    <message>
        <source>Not sent: {0} is not a drill command ({1})</source>
        <extracomment>Seconds the device has to acknowledge (``R``) a command: it does so in its next cycle. A reply is late (the link shown stale) after this share of the receipt&apos;s time. The largest position the wire carries (six digits, docs/protocols.md §3.2).</extracomment>
        <translation>Neodoslané: {0} nie je príkaz vŕtačky ({1})</translation>
    </message>
    <message>
        <source>Motion refused: {0} is no drill position (0…{1})</source>
        <translation>Pohyb odmietnutý: {0} nie je poloha vŕtačky (0…{1})</translation>
    </message>
    <message>
        <source>Link lost: {0}; {1} command(s) dropped</source>
        <translation>Spojenie stratené: {0}; zahodených príkazov: {1}</translation>
    </message>
    <message>
        <source>Link lost: {0}</source>
        <translation>Spojenie stratené: {0}</translation>
    </message>
    <message>
        <source>; {0} command(s) dropped</source>
        <translation>; zahodených príkazov: {0}</translation>
    </message>
    <message>
        <source>home</source>
        <extracomment>The ``D`` may take this much longer than expected (x) and then this many seconds more. A reply is late (the link shown stale) this long after a procedure&apos;s expected end (the receipt&apos;s share is in :mod:`app.machines.drill.queue`). Sent once a link opens, to hear the drill answer: no command has this letter. What each procedure is called in messages.</extracomment>
        <translation>referenčná jazda</translation>
    </message>
    <message>
        <source>move X</source>
        <translation>pohyb X</translation>
    </message>
    <message>
        <source>move Y</source>
        <translation>pohyb Y</translation>
    </message>
    <message>
        <source>drill</source>
        <translation>vŕtanie</translation>
    </message>
    <message>
        <source>pen down</source>
        <translation>pero dole</translation>
    </message>
    <message>
        <source>pen up</source>
        <translation>pero hore</translation>
    </message>
    <message>
        <source>park</source>
        <translation>parkovanie</translation>
    </message>
    <message>
        <source>axis {0}</source>
        <translation>os {0}</translation>
    </message>
    <message>
        <source>moves of {0}</source>
        <extracomment>Seconds of motion in one step of a held jog: what may still run after a release. With Shift (the other speed) a held jog&apos;s steps are this share as long: fine positioning.</extracomment>
        <translation>pohyby {0}</translation>
    </message>
    <message>
        <source>{0} is at the end of its travel</source>
        <translation>{0} je na konci rozsahu posuvu</translation>
    </message>
    <message>
        <source>Jog ends: the end of the travel</source>
        <translation>Posuv končí: koniec rozsahu posuvu</translation>
    </message>
    <message>
        <source>Garbage from the drill dropped: {0}</source>
        <translation>Nezmyselné dáta z vŕtačky zahodené: {0}</translation>
    </message>
    <message>
        <source>Unexpected reply {0} from the drill (waiting for {1})</source>
        <translation>Neočakávaná odpoveď {0} z vŕtačky (čaká sa na {1})</translation>
    </message>
    <message>
        <source>Unexpected reply {0} from the drill</source>
        <translation>Neočakávaná odpoveď {0} z vŕtačky</translation>
    </message>
    <message>
        <source>{0}: it {1}</source>
        <translation>{0}: vŕtačka {1}</translation>
    </message>
    <message>
        <source>The drill {0} ({1})</source>
        <translation>Vŕtačka {0} ({1})</translation>
    </message>
    <message>
        <source>The drill refused {0} ({1})</source>
        <translation>Vŕtačka odmietla {0} ({1})</translation>
    </message>
    <message>
        <source>; {0} queued command(s) dropped</source>
        <translation>; zahodené príkazy vo fronte: {0}</translation>
    </message>
    <message>
        <source>acknowledged twice: the command or its answer was repeated on the way</source>
        <extracomment>Procedures whose second run leaves the machine where one run does (absolute positions, a pen position, homing, parking): repeating them changes nothing on the board. ``R`` heard once more than sent, per letter: their ``D`` is still to come. The letter of the last procedure the station saw finish (a ``D`` repeated on the way). Commands in flight when the link went or fell silent: their R and D may still come.</extracomment>
        <translation>potvrdila príkaz dvakrát: príkaz alebo odpoveď sa cestou zopakovali</translation>
    </message>
    <message>
        <source>finished a procedure the station did not send</source>
        <translation>dokončila procedúru, ktorú stanica neposlala</translation>
    </message>
    <message>
        <source>received a command the station did not send (a line changed on the way)</source>
        <translation>prijala príkaz, ktorý stanica neposlala (riadok sa cestou zmenil)</translation>
    </message>
</context>
<context>
    <name>DrillStepBox</name>
    <message>
        <source>Step through the job (teaching)</source>
        <extracomment>The most characters of a file line shown (the whole line is in its tooltip). The stop&apos;s position (x, y) in the job&apos;s millimetres, or None: the preview rings it.</extracomment>
        <translation>Krokovanie úlohy (výučba)</translation>
    </message>
    <message>
        <source>Previous line</source>
        <translation>Predchádzajúci riadok</translation>
    </message>
    <message>
        <source>Back one line of the job&apos;s file</source>
        <translation>O riadok späť v súbore úlohy</translation>
    </message>
    <message>
        <source>Next line</source>
        <translation>Ďalší riadok</translation>
    </message>
    <message>
        <source>Read the next line of the job&apos;s file (Načti řádek)</source>
        <translation>Načítať ďalší riadok súboru úlohy (Načti řádek)</translation>
    </message>
    <message>
        <source>{0} not sent: not connected</source>
        <translation>{0} neodoslané: nepripojené</translation>
    </message>
    <message>
        <source>{0} not sent: {1}</source>
        <translation>{0} neodoslané: {1}</translation>
    </message>
    <message>
        <source>{0} sent</source>
        <translation>{0} odoslané</translation>
    </message>
    <message>
        <source>No job loaded: open an Excellon file in the Jobs dock</source>
        <translation>Žiadna úloha: otvorte súbor Excellon v paneli Úlohy</translation>
    </message>
    <message>
        <source>{0} lines: Next line reads the first</source>
        <translation>{0} riadkov: Ďalší riadok načíta prvý</translation>
    </message>
    <message>
        <source>line {0} of {1}, position {2} of {3}</source>
        <translation>riadok {0} z {1}, poloha {2} z {3}</translation>
    </message>
    <message>
        <source>line {0} of {1}</source>
        <translation>riadok {0} z {1}</translation>
    </message>
    <message>
        <source>no coordinates on this line</source>
        <translation>na tomto riadku nie sú súradnice</translation>
    </message>
    <message>
        <source>{0} {1} mm = {2} µsteps</source>
        <translation>{0} {1} mm = {2} µkrokov</translation>
    </message>
    <message>
        <source>Send {0} to the drill</source>
        <translation>Poslať {0} vŕtačke</translation>
    </message>
</context>
<context>
    <name>DrillTiming</name>
    <message>
        <source>X step period</source>
        <extracomment>Each constant: its name, its caption, its unit, the factor from the constant&apos;s unit to the field&apos;s (seconds are shown in ms), and the field&apos;s decimals.</extracomment>
        <translation>Perióda kroku X</translation>
    </message>
    <message>
        <source>Y step period</source>
        <translation>Perióda kroku Y</translation>
    </message>
    <message>
        <source>Z step period</source>
        <translation>Perióda kroku Z</translation>
    </message>
    <message>
        <source>Pause going down</source>
        <translation>Prestávka pri spúšťaní</translation>
    </message>
    <message>
        <source>… after every</source>
        <translation>… po každých</translation>
    </message>
    <message>
        <source>Wait at the bottom</source>
        <translation>Čakanie dole</translation>
    </message>
    <message>
        <source>Wait after the return</source>
        <translation>Čakanie po návrate</translation>
    </message>
    <message>
        <source>Return stroke</source>
        <translation>Spätný zdvih</translation>
    </message>
    <message>
        <source>full steps</source>
        <translation>celých krokov</translation>
    </message>
</context>
<context>
    <name>DrillTimingBox</name>
    <message>
        <source>Timing constants (teaching)</source>
        <extracomment>The operator applied constants (a DrillTiming), or went back to the profile&apos;s (None).</extracomment>
        <translation>Časovacie konštanty (výučba)</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Použiť</translation>
    </message>
    <message>
        <source>Count with these constants: the estimate, the timeouts, the emulator</source>
        <translation>Počítať s týmito konštantami: odhad, časové limity, emulátor</translation>
    </message>
    <message>
        <source>Profile values</source>
        <translation>Hodnoty profilu</translation>
    </message>
    <message>
        <source>Back to the machine profile&apos;s constants</source>
        <translation>Späť na konštanty profilu stroja</translation>
    </message>
</context>
<context>
    <name>DynamicsPanel</name>
    <message>
        <source>Parameter</source>
        <extracomment>What the last Apply or snapshot load replaced: (axis, parameter type, wire value). The open &quot;write these differences?&quot; question, while it is asked.</extracomment>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Read</source>
        <extracomment>Each axis has its own column of parameter names: side by side only the first axis&apos;s is shown, stacked each axis block has its own.</extracomment>
        <translation>Načítať</translation>
    </message>
    <message>
        <source>Read every parameter from the device into the fields</source>
        <translation>Načítať všetky parametre zo zariadenia do polí</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Použiť</translation>
    </message>
    <message>
        <source>Write the edited values to the device; it confirms each one</source>
        <translation>Zapísať upravené hodnoty do zariadenia; každú potvrdí</translation>
    </message>
    <message>
        <source>Save snapshot…</source>
        <translation>Uložiť zálohu…</translation>
    </message>
    <message>
        <source>Save every stored parameter to a TOML file</source>
        <translation>Uložiť všetky uložené parametre do súboru TOML</translation>
    </message>
    <message>
        <source>Load snapshot…</source>
        <translation>Načítať zálohu…</translation>
    </message>
    <message>
        <source>Show what a snapshot changes, then write only that</source>
        <translation>Ukázať, čo záloha zmení, a zapísať len to</translation>
    </message>
    <message>
        <source>Undo last write</source>
        <translation>Vrátiť posledný zápis</translation>
    </message>
    <message>
        <source>Write back what the last Apply or load replaced</source>
        <translation>Zapísať späť, čo posledné Použiť alebo načítanie prepísalo</translation>
    </message>
    <message>
        <source>Read only: measured by the device</source>
        <translation>Len na čítanie: meria zariadenie</translation>
    </message>
    <message>
        <source>; at most the mechanical travel, {0} mm</source>
        <translation>; najviac mechanický rozsah posuvu, {0} mm</translation>
    </message>
    <message>
        <source>; current scale CS, the motor gets IRMS = (CS+1)/32 · VFS/(Rsense+20 mΩ)/√2 (VFS {0} V, Rsense {1} Ω)</source>
        <translation>; prúdová škála CS, motor dostáva IRMS = (CS+1)/32 · VFS/(Rsense+20 mΩ)/√2 (VFS {0} V, Rsense {1} Ω)</translation>
    </message>
    <message>
        <source>; → the speed the step timer really runs, where its whole prescaler and reload values cannot give this one</source>
        <translation>; → rýchlosť, ktorou krokový časovač naozaj ide, keď ju jeho celočíselná preddelička a hodnota pretečenia nedokážu nastaviť presne</translation>
    </message>
    <message>
        <source>Reading from the device…</source>
        <translation>Načítavam zo zariadenia…</translation>
    </message>
    <message>
        <source>not a number</source>
        <translation>nie je číslo</translation>
    </message>
    <message>
        <source>✗ not sent</source>
        <translation>✗ neodoslané</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) written</source>
        <translation>
            <numerusform>zapísaná %n hodnota</numerusform>
            <numerusform>zapísané %n hodnoty</numerusform>
            <numerusform>zapísaných %n hodnôt</numerusform>
        </translation>
    </message>
    <message>
        <source>not sent: {0}</source>
        <translation>neodoslané: {0}</translation>
    </message>
    <message>
        <source>Nothing changed</source>
        <translation>Nič sa nezmenilo</translation>
    </message>
    <message>
        <source>Save parameter snapshot</source>
        <translation>Uložiť zálohu parametrov</translation>
    </message>
    <message>
        <source>Parameter snapshots (*.toml)</source>
        <translation>Zálohy parametrov (*.toml)</translation>
    </message>
    <message>
        <source>Load parameter snapshot</source>
        <translation>Načítať zálohu parametrov</translation>
    </message>
    <message>
        <source>Not saved: not read yet: {0} — press Read</source>
        <translation>Neuložené: zatiaľ nenačítané: {0} — stlačte Načítať</translation>
    </message>
    <message>
        <source>Not saved: {0}</source>
        <translation>Neuložené: {0}</translation>
    </message>
    <message>
        <source>Snapshot saved to {0}</source>
        <translation>Záloha uložená do {0}</translation>
    </message>
    <message>
        <source>Not loaded: {0}</source>
        <translation>Nenačítané: {0}</translation>
    </message>
    <message>
        <source>{0}: the device already holds every value</source>
        <translation>{0}: zariadenie už má všetky hodnoty</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) of {0} differ from the device:</source>
        <translation>
            <numerusform>%n hodnota z {0} sa líši od zariadenia:</numerusform>
            <numerusform>%n hodnoty z {0} sa líšia od zariadenia:</numerusform>
            <numerusform>%n hodnôt z {0} sa líši od zariadenia:</numerusform>
        </translation>
    </message>
    <message>
        <source>This snapshot is of another machine ({0}, firmware {1}, {2}), not {3}.</source>
        <translation>Táto záloha je z iného stroja ({0}, firmvér {1}, {2}), nie z {3}.</translation>
    </message>
    <message>
        <source>Write anyway</source>
        <translation>Napriek tomu zapísať</translation>
    </message>
    <message numerus="yes">
        <source>Write %n</source>
        <translation>
            <numerusform>Zapísať %n</numerusform>
            <numerusform>Zapísať %n</numerusform>
            <numerusform>Zapísať %n</numerusform>
        </translation>
    </message>
    <message>
        <source>Snapshot not loaded</source>
        <translation>Záloha nenačítaná</translation>
    </message>
    <message>
        <source>Not written: not connected</source>
        <translation>Nezapísané: nepripojené</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) written from the snapshot; the device confirms each</source>
        <translation>
            <numerusform>Zo zálohy zapísaná %n hodnota; zariadenie ju potvrdí</numerusform>
            <numerusform>Zo zálohy zapísané %n hodnoty; zariadenie každú potvrdí</numerusform>
            <numerusform>Zo zálohy zapísaných %n hodnôt; zariadenie každú potvrdí</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) written back</source>
        <translation>
            <numerusform>späť zapísaná %n hodnota</numerusform>
            <numerusform>späť zapísané %n hodnoty</numerusform>
            <numerusform>späť zapísaných %n hodnôt</numerusform>
        </translation>
    </message>
    <message>
        <source>• edited</source>
        <translation>• upravené</translation>
    </message>
    <message>
        <source>… writing</source>
        <translation>… zapisujem</translation>
    </message>
    <message>
        <source>✓ confirmed</source>
        <translation>✓ potvrdené</translation>
    </message>
    <message>
        <source>✗ refused, kept {0}</source>
        <translation>✗ odmietnuté, ponechané {0}</translation>
    </message>
    <message>
        <source>Asked for {0}</source>
        <translation>Požadované {0}</translation>
    </message>
</context>
<context>
    <name>EchoComposer</name>
    <message>
        <source>Inject echo</source>
        <translation>Vložiť echo</translation>
    </message>
    <message>
        <source>type</source>
        <translation>typ</translation>
    </message>
    <message>
        <source>status</source>
        <translation>stav</translation>
    </message>
    <message>
        <source>value</source>
        <translation>hodnota</translation>
    </message>
    <message>
        <source>µm, µm/s or value</source>
        <translation>µm, µm/s alebo hodnota</translation>
    </message>
    <message>
        <source>Subscriber ID: pick one, or type any hex ID 00…FF</source>
        <translation>ID odberateľa: vyberte alebo napíšte ľubovoľné hex ID 00…FF</translation>
    </message>
    <message>
        <source>subscriber value</source>
        <translation>hodnota odberateľa</translation>
    </message>
    <message>
        <source>Inject</source>
        <translation>Vložiť</translation>
    </message>
    <message>
        <source>Fold this echo into the model as if the device had sent it</source>
        <translation>Premietnuť toto echo do modelu, ako keby ho poslalo zariadenie</translation>
    </message>
    <message>
        <source>A whole number, {0}</source>
        <translation>Celé číslo, {0}</translation>
    </message>
    <message>
        <source>Injected {0}</source>
        <translation>Vložené {0}</translation>
    </message>
</context>
<context>
    <name>EmulatorBox</name>
    <message>
        <source>Emulator</source>
        <translation>Emulátor</translation>
    </message>
    <message>
        <source>No emulator connected: these controls act on the built-in emulator. Turn Simulation on, or connect it on the Link page.</source>
        <translation>Nie je pripojený žiadny emulátor: tieto ovládacie prvky pôsobia na vstavaný emulátor. Zapnite Simuláciu alebo ho pripojte na stránke Spojenie.</translation>
    </message>
    <message>
        <source>Charger connected</source>
        <translation>Nabíjačka pripojená</translation>
    </message>
    <message>
        <source>USB connected</source>
        <translation>USB pripojené</translation>
    </message>
    <message>
        <source>FRAM verification fault (writes refused)</source>
        <translation>Chyba overenia FRAM (zápisy odmietnuté)</translation>
    </message>
    <message>
        <source>State of charge; below 5 % the stage blocks motion</source>
        <translation>Stav nabitia; pod 5 % stolík blokuje pohyb</translation>
    </message>
    <message>
        <source>Board temperature</source>
        <translation>Teplota dosky</translation>
    </message>
    <message>
        <source>Platform rotation rate; the IMU&apos;s yaw integrates it</source>
        <translation>Rýchlosť otáčania plošiny; IMU ju integruje do natočenia</translation>
    </message>
    <message>
        <source>Battery</source>
        <translation>Batéria</translation>
    </message>
    <message>
        <source>Temperature</source>
        <translation>Teplota</translation>
    </message>
    <message>
        <source>Rotation rate</source>
        <translation>Rýchlosť otáčania</translation>
    </message>
    <message>
        <source>{0} end switch</source>
        <extracomment>How often the log view takes in what arrived: fast enough to feel live, slow enough that a 1 kHz stream costs ten redraws a second. Lines the view keeps; the log itself keeps :data:`LOG_CAPACITY` entries (saved in full).</extracomment>
        <translation>{0} koncový spínač</translation>
    </message>
    <message>
        <source>Low</source>
        <translation>Dolný</translation>
    </message>
    <message>
        <source>Close {0}&apos;s low end switch where the axis is now</source>
        <translation>Zopnúť dolný koncový spínač osi {0} tam, kde os práve je</translation>
    </message>
    <message>
        <source>High</source>
        <translation>Horný</translation>
    </message>
    <message>
        <source>Close {0}&apos;s high end switch where the axis is now</source>
        <translation>Zopnúť horný koncový spínač osi {0} tam, kde os práve je</translation>
    </message>
    <message>
        <source>Driver fault</source>
        <translation>Porucha budiča</translation>
    </message>
    <message>
        <source>Over-temperature or stall on {0}&apos;s driver: the axis stops dead</source>
        <translation>Prehriatie alebo zablokovanie budiča osi {0}: os sa okamžite zastaví</translation>
    </message>
    <message>
        <source>Drop link</source>
        <translation>Prerušiť spojenie</translation>
    </message>
    <message>
        <source>Cut the emulated cable; the station reconnects with back-off</source>
        <translation>Prestrihnúť emulovaný kábel; stanica sa znova pripojí s odstupom</translation>
    </message>
    <message>
        <source>Corrupt</source>
        <translation>Poškodiť</translation>
    </message>
    <message>
        <source>Flip a byte in each of the next frames from the device</source>
        <translation>Zmeniť jeden bajt v každom z ďalších rámcov zo zariadenia</translation>
    </message>
</context>
<context>
    <name>FrameLogView</name>
    <message>
        <source>Filter: words that must all occur, e.g. rx charger</source>
        <translation>Filter: slová, ktoré sa musia všetky vyskytovať, napr. rx charger</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pozastaviť</translation>
    </message>
    <message>
        <source>Freeze the view; frames are still recorded and appear on Resume</source>
        <translation>Zmraziť výpis; rámce sa ďalej zaznamenávajú a objavia sa po Pokračovať</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Vymazať</translation>
    </message>
    <message>
        <source>Save…</source>
        <translation>Uložiť…</translation>
    </message>
    <message>
        <source>Save the entries that pass the filter (all when empty)</source>
        <translation>Uložiť záznamy, ktoré prejdú filtrom (prázdny filter: všetky)</translation>
    </message>
    <message>
        <source>Frames sent (TX), received (RX), injected (INJ), rejected (BAD)</source>
        <translation>Odoslané (TX), prijaté (RX), vložené (INJ) a odmietnuté (BAD) rámce</translation>
    </message>
    <message numerus="yes">
        <source>… %n entries not shown: the log keeps the last {0}</source>
        <translation>
            <numerusform>… %n záznam nezobrazený: protokol uchováva posledných {0}</numerusform>
            <numerusform>… %n záznamy nezobrazené: protokol uchováva posledných {0}</numerusform>
            <numerusform>… %n záznamov nezobrazených: protokol uchováva posledných {0}</numerusform>
        </translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Pokračovať</translation>
    </message>
    <message numerus="yes">
        <source>%n entries</source>
        <translation>
            <numerusform>%n záznam</numerusform>
            <numerusform>%n záznamy</numerusform>
            <numerusform>%n záznamov</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source> — paused, %n new not shown</source>
        <translation>
            <numerusform> — pozastavené, %n nový nezobrazený</numerusform>
            <numerusform> — pozastavené, %n nové nezobrazené</numerusform>
            <numerusform> — pozastavené, %n nových nezobrazených</numerusform>
        </translation>
    </message>
    <message>
        <source>Save frame log</source>
        <translation>Uložiť protokol rámcov</translation>
    </message>
    <message>
        <source>Log files (*.log *.txt);;All files (*)</source>
        <translation>Protokoly (*.log *.txt);;Všetky súbory (*)</translation>
    </message>
    <message>
        <source>Could not save: {0}</source>
        <translation>Nedá sa uložiť: {0}</translation>
    </message>
    <message numerus="yes">
        <source>Saved %n entries to {0}</source>
        <translation>
            <numerusform>Uložený %n záznam do {0}</numerusform>
            <numerusform>Uložené %n záznamy do {0}</numerusform>
            <numerusform>Uložených %n záznamov do {0}</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>FrameWords</name>
    <message>
        <source>ok: the oldest unanswered line was accepted</source>
        <translation>ok: najstarší nezodpovedaný riadok prijatý</translation>
    </message>
    <message>
        <source>error {0}: {1}</source>
        <translation>chyba {0}: {1}</translation>
    </message>
    <message>
        <source>alarm {0}: {1}</source>
        <translation>alarm {0}: {1}</translation>
    </message>
    <message>
        <source>{0} at ({1}), feed {2}</source>
        <translation>{0} na ({1}), posuv {2}</translation>
    </message>
    <message>
        <source>, {0} planner blocks free</source>
        <translation>, voľné bloky plánovača: {0}</translation>
    </message>
    <message>
        <source>the board (re)started: &quot;{0}&quot;</source>
        <translation>doska (znovu) naštartovala: &quot;{0}&quot;</translation>
    </message>
    <message>
        <source>message: &quot;{0}&quot;</source>
        <translation>správa: &quot;{0}&quot;</translation>
    </message>
    <message>
        <source>home both axes</source>
        <extracomment>What each drill command letter does (docs/protocols.md, the drill).</extracomment>
        <translation>referenčná jazda oboch osí</translation>
    </message>
    <message>
        <source>move X to {0} µsteps</source>
        <translation>X na {0} µkrokov</translation>
    </message>
    <message>
        <source>move Y to {0} µsteps</source>
        <translation>Y na {0} µkrokov</translation>
    </message>
    <message>
        <source>drill a hole</source>
        <translation>vyvŕtať otvor</translation>
    </message>
    <message>
        <source>pen down</source>
        <translation>pero dole</translation>
    </message>
    <message>
        <source>pen up</source>
        <translation>pero hore</translation>
    </message>
    <message>
        <source>park</source>
        <translation>parkovať</translation>
    </message>
    <message>
        <source>{0} received</source>
        <translation>{0} prijatý</translation>
    </message>
    <message>
        <source>{0} done</source>
        <translation>{0} hotový</translation>
    </message>
    <message>
        <source>{0} refused (error)</source>
        <translation>{0} odmietnutý (chyba)</translation>
    </message>
    <message>
        <source>directions {0}</source>
        <translation>smery {0}</translation>
    </message>
    <message>
        <source>move {0} by {1} counts</source>
        <translation>posun {0} o {1} dielikov</translation>
    </message>
    <message>
        <source>step sizes {0}</source>
        <translation>veľkosti kroku {0}</translation>
    </message>
    <message>
        <source>threads {0}</source>
        <translation>závity {0}</translation>
    </message>
    <message>
        <source>every axis is zero where it stands</source>
        <translation>každá os má nulu tam, kde stojí</translation>
    </message>
    <message>
        <source>ask for the step sizes and threads</source>
        <translation>otázka na veľkosti kroku a závity</translation>
    </message>
    <message>
        <source>stop every axis</source>
        <translation>zastaviť všetky osi</translation>
    </message>
    <message>
        <source>{0} stands at {1} counts</source>
        <translation>{0} stojí na {1} dielikoch</translation>
    </message>
    <message>
        <source>the unit did not understand a command</source>
        <translation>jednotka nerozumela príkazu</translation>
    </message>
</context>
<context>
    <name>Gamepad</name>
    <message>
        <source>Gamepad {0} unplugged: jog stopped</source>
        <translation>Gamepad {0} odpojený: ručný posuv zastavený</translation>
    </message>
    <message>
        <source>Gamepad: left stick + shoulder button (held)</source>
        <translation>Gamepad: ľavá páčka + ramenné tlačidlo (držané)</translation>
    </message>
    <message>
        <source>Jog X and Y while both are held; pushed further, faster (G-code boards)</source>
        <translation>Posuv v osiach X a Y, kým sú obe držané; páčka vychýlená ďalej = rýchlejšie (G-kódové dosky)</translation>
    </message>
    <message>
        <source>Gamepad: right stick up/down + shoulder button</source>
        <translation>Gamepad: pravá páčka hore/dole + ramenné tlačidlo</translation>
    </message>
    <message>
        <source>Jog Z while both are held, on machines with a Z axis</source>
        <translation>Posuv v osi Z, kým sú obe držané, pri strojoch s osou Z</translation>
    </message>
    <message>
        <source>Joystick: stick + trigger (held)</source>
        <translation>Joystick: páka + spúšť (držané)</translation>
    </message>
    <message>
        <source>Jog X and Y while both are held</source>
        <translation>Posuv v osiach X a Y, kým sú obe držané</translation>
    </message>
    <message>
        <source>Let go of the stick or the button, or unplug</source>
        <translation>Pustiť páčku alebo tlačidlo, alebo odpojiť</translation>
    </message>
    <message>
        <source>The jog stops at once</source>
        <translation>Posuv sa okamžite zastaví</translation>
    </message>
    <message>
        <source>&amp;Gamepad…</source>
        <translation>&amp;Gamepad…</translation>
    </message>
    <message>
        <source>Gamepad unavailable: {0}</source>
        <translation>Gamepad nie je k dispozícii: {0}</translation>
    </message>
    <message>
        <source>Gamepad: off</source>
        <translation>Gamepad: vypnutý</translation>
    </message>
    <message>
        <source>Gamepad: starting…</source>
        <translation>Gamepad: spúšťa sa…</translation>
    </message>
    <message>
        <source>Gamepad: {0}</source>
        <translation>Gamepad: {0}</translation>
    </message>
    <message>
        <source>Gamepad: waiting for {0}</source>
        <translation>Gamepad: čaká sa na {0}</translation>
    </message>
    <message>
        <source>Gamepad: none plugged in</source>
        <translation>Gamepad: žiadny nie je pripojený</translation>
    </message>
    <message>
        <source>StepDeck — gamepad</source>
        <translation>StepDeck — gamepad</translation>
    </message>
    <message>
        <source>&amp;Jog with a gamepad or joystick</source>
        <translation>&amp;Ručný posuv gamepadom alebo joystickom</translation>
    </message>
    <message>
        <source>&amp;Device:</source>
        <translation>&amp;Zariadenie:</translation>
    </message>
    <message>
        <source>The first one found</source>
        <translation>Prvé nájdené</translation>
    </message>
    <message>
        <source>Nothing jogs unless the enable button is held with the stick: a dropped pad or a drifting stick moves nothing. The pad jogs only while a StepDeck window is active, and a job under way refuses it as it refuses the keys.</source>
        <translation>Nič sa nepohne, kým nie je s páčkou držané aj povoľovacie tlačidlo: spadnutý gamepad ani ubiehajúca páčka strojom nepohnú. Gamepad posúva, len keď je aktívne okno StepDecku, a prebiehajúca úloha ho odmietne rovnako ako klávesy.</translation>
    </message>
</context>
<context>
    <name>GcodeDriver</name>
    <message>
        <source>The machine holds (a feed hold: its hold button, the Hold button here, or a &apos;!&apos; that reached it on the wire): the job is paused at {0}. Resume lets it go on (cycle start).</source>
        <extracomment>Station-clock seconds between checkpoint writes while lines stream (each write is an fsync). Station-clock seconds between &quot;operation under way&quot; announcements while lines stream. The modal words a program is checked in (absolute, millimetres, XY plane), sent before its first line where the machine has them: a jog or a console line may have changed them. The work offset when the job began: program coordinates are machine less it. Where the machine stood when the job began, in the program&apos;s coordinates (None when the run began elsewhere than operation 0): standing there again after a fault may mean nothing ran as well as that the file came back to it. The running job&apos;s way to the wire (None without a stream or a session). The last ``[GC:…]`` heard while the set-up is confirmed, awaiting its line&apos;s ``ok``. Checkpoints while lines stream, and &quot;operation under way&quot; announcements, are paced. ``$G`` was sent after the set-up: nothing of the job goes before its answer. The operation the last resume went back to (a refused way back fails there). Set-up and way-back lines sent and not yet answered: the job waits for them, so that none of its lines runs on a machine they did not set up. A pause took back the set-up before it went: it goes again first on the resume. The board reset itself since the job began or last resumed: its position is lost. The operation the operator chose to resume from (ResumeChoice), not yet gone on. A ResumeChoice waits for the operator&apos;s pick. Judges whether the board stands before anything of a resume goes (see standing.py). The board went into a feed hold the station did not ask for (its hold button, or a ``!`` that reached it on the wire): the job is paused, and its resume is a cycle start — the board still has every line it was sent. The operator&apos;s chosen start (its state rebuilt once the machine is looked at). follows ALARM:3 with its banner) is kept for the Resume, not said again.</extracomment>
        <translation>Stroj stojí v pozdržaní (feed hold: jeho tlačidlo, tunajšie tlačidlo Pozdržať, alebo znak „!“, ktorý k nemu dorazil po vedení): úloha je pozastavená na {0}. Pokračovať ju nechá ísť ďalej (cycle start).</translation>
    </message>
    <message>
        <source>The machine restarted during the job (its reset button, its power, or its port reopened) and may have lost its position: the job is paused. Home it ($H) or check where the tool is (clear an alarm with $X), then choose the line to resume from; {0} operation(s) from {1} were sent but not proven run.</source>
        <translation>Stroj sa počas úlohy reštartoval (tlačidlom reset, napájaním alebo opätovným otvorením portu) a mohol stratiť svoju polohu: úloha je pozastavená. Nabehnite s ním do východiskovej polohy ($H) alebo skontrolujte, kde je nástroj (alarm zrušte pomocou $X), a potom zvoľte riadok, od ktorého pokračovať; {0} operácií od {1} bolo odoslaných, ale ich vykonanie nie je preukázané.</translation>
    </message>
    <message>
        <source>{0} operation(s) from {1} were sent but their running is not proven: choose the line to resume from (the candidates are highlighted).</source>
        <translation>{0} operácií od {1} bolo odoslaných, ale ich vykonanie nie je preukázané: zvoľte riadok, od ktorého pokračovať (kandidáti sú zvýraznení).</translation>
    </message>
    <message>
        <source>Some of them draw: resuming too early draws a stroke twice, too late leaves one out.</source>
        <translation>Niektoré z nich kreslia: pokračovanie príliš skoro nakreslí ťah dvakrát, príliš neskoro jeden vynechá.</translation>
    </message>
    <message>
        <source>The machine is in alarm: the job stays paused. Check the machine, clear the alarm (home it with $H, or unlock it with $X if its position is still right), then Resume.</source>
        <translation>Stroj je v alarme: úloha zostáva pozastavená. Skontrolujte stroj, zrušte alarm (nájazdom do východiskovej polohy príkazom $H, alebo odomknutím príkazom $X, ak jeho poloha stále zodpovedá) a potom dajte Pokračovať.</translation>
    </message>
    <message>
        <source>The machine went into alarm {0} ({1}) during the job and stopped: the job is paused at {2}. Clear the alarm (home it with $H, or unlock it with $X if its position is still right), then Resume: the job goes on from what is proven run.</source>
        <translation>Stroj počas úlohy prešiel do alarmu {0} ({1}) a zastavil sa: úloha je pozastavená na {2}. Zrušte alarm (nabehnite do východiskovej polohy pomocou $H, alebo ho odomknite pomocou $X, ak je jeho poloha stále správna), potom Pokračovať: úloha pokračuje od toho, čo je preukázateľne vykonané.</translation>
    </message>
</context>
<context>
    <name>GcodeEmulatorBox</name>
    <message>
        <source>Emulated board</source>
        <translation>Emulovaná doska</translation>
    </message>
    <message>
        <source>Hold</source>
        <translation>Pozastaviť</translation>
    </message>
    <message>
        <source>The board&apos;s feed-hold button</source>
        <translation>Tlačidlo pozastavenia posuvu na doske</translation>
    </message>
    <message>
        <source>Cycle start</source>
        <translation>Štart cyklu</translation>
    </message>
    <message>
        <source>The board&apos;s cycle-start button</source>
        <translation>Tlačidlo štartu cyklu na doske</translation>
    </message>
    <message>
        <source>ALARM code (1: hard limit, 2: soft limit, 3: reset in motion…)</source>
        <translation>Kód ALARM (1: koncový spínač, 2: softvérový limit, 3: reset počas pohybu…)</translation>
    </message>
    <message>
        <source>Raise alarm</source>
        <translation>Vyvolať alarm</translation>
    </message>
    <message>
        <source>ALARM code</source>
        <translation>Kód ALARM</translation>
    </message>
    <message>
        <source>White button</source>
        <translation>Biele tlačidlo</translation>
    </message>
    <message>
        <source>The winder&apos;s white button: the first press switches the holding current off (turn the axes by hand), the second sets the zero there (X = board radius)</source>
        <translation>Biele tlačidlo navíjačky: prvé stlačenie vypne udržiavací prúd (osami možno otáčať rukou), druhé tam nastaví nulu (X = polomer dosky)</translation>
    </message>
    <message>
        <source>Turn {0} by hand (its driver must be off)</source>
        <translation>Otočiť osou {0} rukou (jej driver musí byť vypnutý)</translation>
    </message>
    <message>
        <source>drivers off: turn the axes by hand, then press again</source>
        <translation>drivery vypnuté: otočte osami rukou a stlačte znova</translation>
    </message>
    <message>
        <source>zero set here (X = board radius)</source>
        <translation>nula nastavená tu (X = polomer dosky)</translation>
    </message>
    <message>
        <source>ignored: the machine is busy</source>
        <translation>ignorované: stroj pracuje</translation>
    </message>
    <message>
        <source>{0} holds: its driver is on</source>
        <translation>{0} drží: jej driver je zapnutý</translation>
    </message>
</context>
<context>
    <name>GcodePanel</name>
    <message>
        <source>Machine</source>
        <translation>Stroj</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Stav</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>Poloha</translation>
    </message>
    <message>
        <source>Home</source>
        <translation>Referencia</translation>
    </message>
    <message>
        <source>Back to the origin ($H or G28)</source>
        <translation>Referenčný posuv do počiatku ($H alebo G28)</translation>
    </message>
    <message>
        <source>Pen up</source>
        <translation>Pero hore</translation>
    </message>
    <message>
        <source>Lift the pen ({0})</source>
        <translation>Zdvihnúť pero ({0})</translation>
    </message>
    <message>
        <source>Pen down</source>
        <translation>Pero dole</translation>
    </message>
    <message>
        <source>Lower the pen ({0})</source>
        <translation>Spustiť pero ({0})</translation>
    </message>
    <message>
        <source>Hold !</source>
        <translation>Pozastaviť !</translation>
    </message>
    <message>
        <source>Feed hold: decelerate and stop</source>
        <translation>Pozastavenie posuvu: spomaliť a zastaviť</translation>
    </message>
    <message>
        <source>Resume ~</source>
        <translation>Pokračovať ~</translation>
    </message>
    <message>
        <source>Carry on after a hold or M0</source>
        <translation>Pokračovať po pozastavení alebo M0</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Reset</translation>
    </message>
    <message>
        <source>Soft reset (Ctrl-X): stop and drop everything buffered</source>
        <translation>Softvérový reset (Ctrl-X): zastaviť a zahodiť všetko vo vyrovnávacej pamäti</translation>
    </message>
    <message>
        <source>Console</source>
        <translation>Konzola</translation>
    </message>
    <message>
        <source>G0 X10 Y10, $$, M3 …  (Up/Down: history)</source>
        <translation>G0 X10 Y10, $$, M3 …  (Hore/Dole: história)</translation>
    </message>
    <message>
        <source>Send</source>
        <translation>Odoslať</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Vymazať</translation>
    </message>
    <message>
        <source>Clear the console</source>
        <translation>Vymazať konzolu</translation>
    </message>
    <message>
        <source>Zero by hand</source>
        <extracomment>A GRBL alarm or error explained, with what clears it (hidden without one).</extracomment>
        <translation>Nulovanie rukou</translation>
    </message>
    <message>
        <source>Release the motors, turn the base and move the needle by hand until nail 0 faces the needle and the needle stands at the board&apos;s edge, then Zero here: A 0, X the board radius, Z 0. Nothing moves.</source>
        <translation>Uvoľnite motory, rukou otočte podstavou a posuňte ihlu, kým nebude klinec 0 oproti ihle a ihla na okraji dosky, potom Nula tu: A 0, X polomer dosky, Z 0. Nič sa nepohne.</translation>
    </message>
    <message>
        <source>Board radius: X where the needle meets the board&apos;s edge</source>
        <translation>Polomer dosky: X, kde ihla stojí na okraji dosky</translation>
    </message>
    <message>
        <source>Release motors</source>
        <translation>Uvoľniť motory</translation>
    </message>
    <message>
        <source>Switch every driver off (M18) so the axes turn by hand; refused while a job is under way or the machine moves</source>
        <translation>Vypnúť všetky drivery (M18), aby sa osami dalo otáčať rukou; odmietnuté, kým beží úloha alebo sa stroj pohybuje</translation>
    </message>
    <message>
        <source>Zero here</source>
        <translation>Nula tu</translation>
    </message>
    <message>
        <source>The axes stand at the zero: A 0, X the board radius, Z 0 (G92); nothing moves</source>
        <translation>Osi stoja na nule: A 0, X polomer dosky, Z 0 (G92); nič sa nepohne</translation>
    </message>
    <message>
        <source>Board radius</source>
        <translation>Polomer dosky</translation>
    </message>
    <message>
        <source>Beyond the travel</source>
        <translation>Mimo rozsahu posuvu</translation>
    </message>
    <message>
        <source>{0}.

Send it to the machine anyway?</source>
        <translation>{0}.

Napriek tomu odoslať do stroja?</translation>
    </message>
    <message>
        <source>! {0}: not sent (beyond the travel)</source>
        <translation>! {0}: neodoslané (mimo rozsahu posuvu)</translation>
    </message>
    <message>
        <source>! {0}: not sent</source>
        <translation>! {0}: neodoslané</translation>
    </message>
    <message numerus="yes">
        <source>! soft reset: %n unanswered line(s) dropped</source>
        <translation>
            <numerusform>! softvérový reset: zahodený %n nepotvrdený riadok</numerusform>
            <numerusform>! softvérový reset: zahodené %n nepotvrdené riadky</numerusform>
            <numerusform>! softvérový reset: zahodených %n nepotvrdených riadkov</numerusform>
        </translation>
    </message>
    <message>
        <source>{0}   feed {1}</source>
        <translation>{0}   posuv {1}</translation>
    </message>
</context>
<context>
    <name>GcodeReplyBox</name>
    <message>
        <source>Inject a reply (as if the device sent it)</source>
        <translation>Vložiť odpoveď (ako keby ju poslalo zariadenie)</translation>
    </message>
    <message>
        <source>Inject</source>
        <translation>Vložiť</translation>
    </message>
    <message>
        <source>Inject {0}</source>
        <translation>Vložiť {0}</translation>
    </message>
    <message>
        <source>Not injected: {0}</source>
        <translation>Nevložené: {0}</translation>
    </message>
    <message>
        <source>banner</source>
        <extracomment>Replies a developer reaches for most, for the pane&apos;s quick buttons.</extracomment>
        <translation>úvodné hlásenie</translation>
    </message>
</context>
<context>
    <name>GcodeSession</name>
    <message>
        <source>Stopped: {0} line(s) not run</source>
        <extracomment>A stop resets the device this long after its hold at the latest, standing or not. The stop under way ends a jog: no &quot;lines not run&quot; message for it. When the hold went out, while its reset has not (None: no stop under way). A stop went out and no report since its reset has shown the board standing: on a silent line its hold and reset may both have been lost.</extracomment>
        <translation>Zastavené: nevykonaných riadkov: {0}</translation>
    </message>
    <message>
        <source>Jog ends: the end of the travel</source>
        <extracomment>Each held-arrow step is this much motion, and the next goes only while the device&apos;s planner holds fewer than JOG_BLOCKS_AHEAD blocks. Fraction of an axis&apos;s top speed a held arrow jogs at. A jog step shorter than this (the travel&apos;s end reached) is not sent. Whether the board takes ``$J=`` jogs (0x85 cancels them). Without ``Bf:`` in the reports: when each planned jog step should be done (clock). Where the steps sent so far take each axis (None: no jog under way). A jog cancel was sent and the board still reports Jog: a new jog waits.</extracomment>
        <translation>Posuv končí: koniec rozsahu posuvu</translation>
    </message>
    <message>
        <source>Link lost: {0}; {1} unanswered line(s)</source>
        <translation>Spojenie stratené: {0}; nepotvrdených riadkov: {1}</translation>
    </message>
    <message>
        <source>Link lost: {0}</source>
        <translation>Spojenie stratené: {0}</translation>
    </message>
    <message>
        <source>Garbage from the device dropped: {0}</source>
        <translation>Nezmyselné dáta zo zariadenia zahodené: {0}</translation>
    </message>
    <message>
        <source>Machine alarm {0}: {1}</source>
        <translation>Alarm stroja {0}: {1}</translation>
    </message>
    <message>
        <source>The device reset: {0} unanswered line(s) were not run</source>
        <translation>Zariadenie sa resetovalo: nevykonané nezodpovedané riadky: {0}</translation>
    </message>
    <message>
        <source>The device&apos;s replies could not be read ({0}): stopping</source>
        <translation>Odpovede zariadenia nemožno prečítať ({0}): zastavujem</translation>
    </message>
    <message>
        <source>A reply arrived for no line (ignored)</source>
        <translation>Prišla odpoveď bez riadku (ignorovaná)</translation>
    </message>
    <message>
        <source>{0} refused: error {1}, {2}</source>
        <translation>{0} odmietnutý: chyba {1}, {2}</translation>
    </message>
    <message>
        <source>The board holds {0} byte(s) of a line whose end never came (lost on the way) and waits for it: it stands idle, so it is reset, keeping its position, and what it ran is looked at again</source>
        <extracomment>A line cut on the wire, its start stuck in the board&apos;s buffer (stuck_line.py). The board&apos;s buffer against the bytes counted unanswered (byte_count.py). Planner blocks the device has, learned from its ``Bf:`` reports (0: unknown). The pen (a GRBL plotter&apos;s spindle) against the lines answered (pen_watch.py).</extracomment>
        <translation>Doska drží {0} bajt(ov) riadku, ktorého koniec nikdy neprišiel (stratil sa cestou), a čaká naň: stojí v pokoji, preto je resetovaná so zachovaním polohy a to, čo vykonala, sa znovu preverí</translation>
    </message>
    <message>
        <source>{0} line(s) unanswered while the board stands idle; waiting for its answer (without Bf: in its reports it cannot show it has them)</source>
        <translation>Nezodpovedané riadky, kým doska stojí v pokoji: {0}; čaká sa na jej odpoveď (bez Bf: v hláseniach nemôže ukázať, že ich má)</translation>
    </message>
    <message>
        <source>{0} line(s) sent never reached the board: it has taken every byte it got and stands idle short of where they end; it is reset, keeping its position, and what it ran is looked at again</source>
        <translation>{0} odoslaných riadkov nikdy nedorazilo do dosky: prevzala každý bajt, ktorý dostala, a stojí v pokoji pred miestom, kde končia; je resetovaná so zachovaním polohy a to, čo vykonala, sa znovu preverí</translation>
    </message>
    <message>
        <source>{0} answer(s) from the board were lost on the way; it has taken and run every line sent, so they count as answered</source>
        <translation>Odpovede dosky stratené cestou: {0}; prevzala a vykonala každý odoslaný riadok, takže sa počítajú ako zodpovedané</translation>
    </message>
    <message>
        <source>The board holds {0} byte(s) more than were sent and not answered (a line or an answer arrived twice on the way): the lines it holds may be garbled, so it is stopped before it runs them</source>
        <translation>Doska drží o {0} bajt(ov) viac, než bolo odoslané a nezodpovedané (riadok alebo odpoveď dorazili cestou dvakrát): riadky, ktoré drží, môžu byť poškodené, preto je zastavená skôr, než ich vykoná</translation>
    </message>
    <message>
        <source>The board holds {0} byte(s) where the lines sent and not yet run make at least {1}: {2} byte(s) were lost on the way inside a line waiting in its buffer (in “{3}” or a line behind it), so it is stopped before it runs it</source>
        <translation>Doska drží {0} bajt(ov), kde odoslané a zatiaľ nevykonané riadky dávajú aspoň {1}: cestou sa stratilo {2} bajt(ov) vnútri riadku čakajúceho v jej vyrovnávacej pamäti (v „{3}“ alebo v riadku za ním), preto je zastavená skôr, než ho vykoná</translation>
    </message>
    <message>
        <source>; {0} unanswered line(s)</source>
        <translation>; nezodpovedaných riadkov: {0}</translation>
    </message>
    <message>
        <source>Not sent without confirmation: {0}</source>
        <extracomment>No reply for this long: the link is lost (:mod:`~app.machines.gcode.timing`). Status queries unanswered before the link is shown stale (amber), and the least time. The lines of one write, in order (list[SentLine]): what hears every line of a running job listens here, once a batch, not once a line. Lines of the followed job were answered (counted there): once per batch of replies. A reply line worth showing the operator (the console): its text. The device was reset (banner seen or reset sent): whatever was unanswered is gone. The streaming loop and its ``ok`` accounting, on the transport&apos;s reader thread. Line serials, taken under the feeder&apos;s lock: both threads number lines. A status report since the last line was answered showed the machine idle (written under the feeder&apos;s lock: a job&apos;s line queued on the reader thread clears it). Silence shown amber: a few status queries (one each ``status_ms``) unanswered. GRBL&apos;s lock after a hard or soft limit: silent until a reset (limit_lock.py). Whether the last :attr:`reset` was the board&apos;s own (a banner nobody here asked for: its reset button, a power dip), not a soft reset the station sent. The board&apos;s work coordinate offset last reported (GRBL&apos;s WCO:), None before any. What the followed job had as the last status report was read (its snapshot). After a silence: when the board was first heard again, the first status report made after that had settled, and whether a banner came meanwhile.</extracomment>
        <translation>Bez potvrdenia neodoslané: {0}</translation>
    </message>
    <message>
        <source>Not sent: {0} ({1})</source>
        <translation>Neodoslané: {0} ({1})</translation>
    </message>
    <message>
        <source>Not sent: {0} (not connected)</source>
        <translation>Neodoslané: {0} (nepripojené)</translation>
    </message>
    <message>
        <source>it restarted meanwhile (its banner came), so what it had is gone</source>
        <translation>medzitým sa reštartovalo (prišiel jeho úvodný text), takže čo malo, je preč</translation>
    </message>
    <message>
        <source>it is in alarm</source>
        <translation>je v alarme</translation>
    </message>
    <message>
        <source>{0} line(s) still unanswered while the board stands idle, and its reports cannot show whether it has them: it is reset, keeping its position, and what it ran is looked at again</source>
        <translation>{0} riadok/riadkov stále bez odpovede, kým doska stojí nečinne, a jej hlásenia nemôžu ukázať, či ich má: doska sa resetuje, poloha zostáva, a čo vykonala, sa posúdi znova</translation>
    </message>
    <message>
        <source>in alarm: reset to continue</source>
        <extracomment>The alarms after which GRBL waits for a reset (protocol.c): hard and soft limits. GRBL&apos;s words after them (report.c, ``MESSAGE_CRITICAL_EVENT``).</extracomment>
        <translation>v alarme: pokračujte resetom</translation>
    </message>
</context>
<context>
    <name>GrblAlarmBand</name>
    <message>
        <source>Unlock ($X)</source>
        <translation>Odomknúť ($X)</translation>
    </message>
    <message>
        <source>Home ($H)</source>
        <translation>Východisková poloha ($H)</translation>
    </message>
    <message>
        <source>Reset (Ctrl-X)</source>
        <translation>Reset (Ctrl-X)</translation>
    </message>
</context>
<context>
    <name>GrblCodes</name>
    <message>
        <source>Home the machine ($H): its position is likely lost.</source>
        <extracomment>The actions, in words (each code says one).</extracomment>
        <translation>Nabehnite strojom do východiskovej polohy ($H): jeho poloha je pravdepodobne stratená.</translation>
    </message>
    <message>
        <source>Check the limit switches and their wiring, then home the machine ($H).</source>
        <translation>Skontrolujte koncové spínače a ich zapojenie, potom nabehnite do východiskovej polohy ($H).</translation>
    </message>
    <message>
        <source>Reset the board (Ctrl-X): it answers nothing until then. Check the limit switches, then home the machine ($H), or unlock it ($X) only if its position is surely right.</source>
        <extracomment>After a hard or soft limit GRBL answers nothing until it is reset (limit_lock.py).</extracomment>
        <translation>Resetujte dosku (Ctrl-X): dovtedy neodpovedá na nič. Skontrolujte koncové spínače, potom vykonajte referenčnú jazdu ($H), alebo stroj odomknite ($X), len ak je jeho poloha isto správna.</translation>
    </message>
    <message>
        <source>Reset the board (Ctrl-X): it answers nothing until then. Then unlock it ($X): its position is kept; or home it ($H).</source>
        <translation>Resetujte dosku (Ctrl-X): dovtedy neodpovedá na nič. Potom stroj odomknite ($X): jeho poloha zostala zachovaná; alebo vykonajte referenčnú jazdu ($H).</translation>
    </message>
    <message>
        <source>Check the probe and its wiring, then unlock ($X).</source>
        <translation>Skontrolujte sondu a jej zapojenie, potom odomknite ($X).</translation>
    </message>
    <message>
        <source>Close the safety door, then home the machine ($H).</source>
        <translation>Zatvorte bezpečnostné dvierka, potom nabehnite do východiskovej polohy ($H).</translation>
    </message>
    <message>
        <source>Correct the line: the board did not run it.</source>
        <translation>Opravte riadok: doska ho nevykonala.</translation>
    </message>
    <message>
        <source>Check the board&apos;s settings ($$).</source>
        <translation>Skontrolujte nastavenia dosky ($$).</translation>
    </message>
    <message>
        <source>Wait until the machine stands idle, then send it again.</source>
        <translation>Počkajte, kým stroj stojí v pokoji, a pošlite príkaz znova.</translation>
    </message>
    <message>
        <source>Clear the alarm first: home the machine ($H), or unlock it ($X).</source>
        <translation>Najprv zrušte alarm: nabehnite do východiskovej polohy ($H), alebo stroj odomknite ($X).</translation>
    </message>
    <message>
        <source>Close the safety door.</source>
        <translation>Zatvorte bezpečnostné dvierka.</translation>
    </message>
    <message>
        <source>Jog within the machine&apos;s travel.</source>
        <translation>Posúvajte len v rozsahu pojazdu stroja.</translation>
    </message>
    <message>
        <source>Hard limit has been triggered. Machine position is likely lost due to sudden halt. Re-homing is highly recommended.</source>
        <translation>Zopol koncový spínač. Poloha stroja je po náhlom zastavení pravdepodobne stratená. Dôrazne odporúčame znova nabehnúť do východiskovej polohy.</translation>
    </message>
    <message>
        <source>Soft limit alarm. G-code motion target exceeds machine travel. Machine position retained. Alarm may be safely unlocked.</source>
        <translation>Softvérový limit. Cieľ pohybu G-kódu leží mimo pojazdu stroja. Poloha stroja zostala zachovaná. Alarm možno bezpečne odomknúť.</translation>
    </message>
    <message>
        <source>Reset while in motion. Machine position is likely lost due to sudden halt. Re-homing is highly recommended.</source>
        <translation>Reset počas pohybu. Poloha stroja je po náhlom zastavení pravdepodobne stratená. Dôrazne odporúčame znova nabehnúť do východiskovej polohy.</translation>
    </message>
    <message>
        <source>Probe fail. Probe is not in the expected initial state before starting probe cycle.</source>
        <translation>Chyba sondy. Sonda nie je pred začiatkom meracieho cyklu v očakávanom východiskovom stave.</translation>
    </message>
    <message>
        <source>Probe fail. Probe did not contact the workpiece within the programmed travel.</source>
        <translation>Chyba sondy. Sonda sa v naprogramovanej dráhe nedotkla obrobku.</translation>
    </message>
    <message>
        <source>Homing fail. The active homing cycle was reset.</source>
        <translation>Chyba nábehu do východiskovej polohy. Prebiehajúci cyklus bol resetovaný.</translation>
    </message>
    <message>
        <source>Homing fail. Safety door was opened during homing cycle.</source>
        <translation>Chyba nábehu do východiskovej polohy. Počas cyklu boli otvorené bezpečnostné dvierka.</translation>
    </message>
    <message>
        <source>Homing fail. Pull off travel failed to clear limit switch. Try increasing pull-off setting or check wiring.</source>
        <translation>Chyba nábehu do východiskovej polohy. Odjazd od spínača ho neuvoľnil. Skúste zväčšiť odjazd (pull-off) alebo skontrolujte zapojenie.</translation>
    </message>
    <message>
        <source>Homing fail. Could not find limit switch within search distances. Try increasing max travel, decreasing pull-off distance, or check wiring.</source>
        <translation>Chyba nábehu do východiskovej polohy. Koncový spínač sa v hľadanej vzdialenosti nenašiel. Skúste zväčšiť maximálny pojazd, zmenšiť odjazd (pull-off) alebo skontrolujte zapojenie.</translation>
    </message>
    <message>
        <source>Homing fail. Second dual axis limit switch failed to trigger within configured search distance after first. Try increasing trigger fail distance or check wiring.</source>
        <translation>Chyba nábehu do východiskovej polohy. Druhý spínač zdvojenej osi nezopol v nastavenej vzdialenosti po prvom. Skúste zväčšiť túto vzdialenosť alebo skontrolujte zapojenie.</translation>
    </message>
    <message>
        <source>G-code words consist of a letter and a value. Letter was not found.</source>
        <translation>Slovo G-kódu tvorí písmeno a hodnota. Písmeno chýba.</translation>
    </message>
    <message>
        <source>Missing the expected G-code word value or numeric value format is not valid.</source>
        <translation>Chýba očakávaná hodnota slova G-kódu alebo číslo nemá platný tvar.</translation>
    </message>
    <message>
        <source>Grbl &apos;$&apos; system command was not recognized or supported.</source>
        <translation>Systémový príkaz &apos;$&apos; GRBL nepozná alebo nepodporuje.</translation>
    </message>
    <message>
        <source>Negative value received for an expected positive value.</source>
        <translation>Záporná hodnota tam, kde sa očakáva kladná.</translation>
    </message>
    <message>
        <source>Homing cycle failure. Homing is not enabled via settings.</source>
        <translation>Nábeh do východiskovej polohy zlyhal. V nastaveniach nie je povolený.</translation>
    </message>
    <message>
        <source>Minimum step pulse time must be greater than 3usec.</source>
        <translation>Najkratší krokový impulz musí byť dlhší ako 3 µs.</translation>
    </message>
    <message>
        <source>An EEPROM read failed. Auto-restoring affected EEPROM to default values.</source>
        <translation>Čítanie EEPROM zlyhalo. Dotknuté hodnoty EEPROM sa obnovujú na predvolené.</translation>
    </message>
    <message>
        <source>Grbl &apos;$&apos; command cannot be used unless Grbl is IDLE. Ensures smooth operation during a job.</source>
        <translation>Príkaz &apos;$&apos; možno použiť len v pokoji (Idle). Tak nenaruší bežiacu úlohu.</translation>
    </message>
    <message>
        <source>G-code commands are locked out during alarm or jog state.</source>
        <translation>Príkazy G-kódu sú počas alarmu alebo ručného posuvu zablokované.</translation>
    </message>
    <message>
        <source>Soft limits cannot be enabled without homing also enabled.</source>
        <translation>Softvérové limity nemožno zapnúť bez povoleného nábehu do východiskovej polohy.</translation>
    </message>
    <message>
        <source>Max characters per line exceeded. Received command line was not executed.</source>
        <translation>Prekročený najväčší počet znakov na riadku. Prijatý riadok nebol vykonaný.</translation>
    </message>
    <message>
        <source>Grbl &apos;$&apos; setting value cause the step rate to exceed the maximum supported.</source>
        <translation>Hodnota nastavenia &apos;$&apos; by prekročila najvyššiu podporovanú krokovú frekvenciu.</translation>
    </message>
    <message>
        <source>Safety door detected as opened and door state initiated.</source>
        <translation>Bezpečnostné dvierka sú otvorené; doska prešla do stavu Door.</translation>
    </message>
    <message>
        <source>Build info or startup line exceeded EEPROM line length limit. Line not stored.</source>
        <translation>Informácia o zostavení alebo štartovací riadok presahuje dĺžku riadku v EEPROM. Riadok nebol uložený.</translation>
    </message>
    <message>
        <source>Jog target exceeds machine travel. Jog command has been ignored.</source>
        <translation>Cieľ ručného posuvu leží mimo pojazdu stroja. Príkaz bol ignorovaný.</translation>
    </message>
    <message>
        <source>Jog command has no &apos;=&apos; or contains prohibited g-code.</source>
        <translation>Príkaz ručného posuvu nemá &apos;=&apos; alebo obsahuje zakázaný G-kód.</translation>
    </message>
    <message>
        <source>Laser mode requires PWM output.</source>
        <translation>Laserový režim vyžaduje výstup PWM.</translation>
    </message>
    <message>
        <source>Unsupported or invalid g-code command found in block.</source>
        <translation>Riadok obsahuje nepodporovaný alebo neplatný príkaz G-kódu.</translation>
    </message>
    <message>
        <source>More than one g-code command from same modal group found in block.</source>
        <translation>Riadok obsahuje viac príkazov G-kódu z tej istej modálnej skupiny.</translation>
    </message>
    <message>
        <source>Feed rate has not yet been set or is undefined.</source>
        <translation>Rýchlosť posuvu ešte nebola nastavená.</translation>
    </message>
    <message>
        <source>G-code command in block requires an integer value.</source>
        <translation>Príkaz G-kódu na riadku vyžaduje celé číslo.</translation>
    </message>
    <message>
        <source>More than one g-code command that requires axis words found in block.</source>
        <translation>Riadok obsahuje viac príkazov G-kódu, ktoré vyžadujú slová osí.</translation>
    </message>
    <message>
        <source>Repeated g-code word found in block.</source>
        <translation>Riadok obsahuje opakované slovo G-kódu.</translation>
    </message>
    <message>
        <source>No axis words found in block for g-code command or current modal state which requires them.</source>
        <translation>Riadok nemá slová osí, ktoré príkaz alebo aktuálny modálny stav vyžaduje.</translation>
    </message>
    <message>
        <source>Line number value is invalid.</source>
        <translation>Číslo riadku je neplatné.</translation>
    </message>
    <message>
        <source>G-code command is missing a required value word.</source>
        <translation>Príkazu G-kódu chýba povinné slovo s hodnotou.</translation>
    </message>
    <message>
        <source>G59.x work coordinate systems are not supported.</source>
        <translation>Pracovné súradnicové systémy G59.x nie sú podporované.</translation>
    </message>
    <message>
        <source>G53 only allowed with G0 and G1 motion modes.</source>
        <translation>G53 je povolené len s pohybmi G0 a G1.</translation>
    </message>
    <message>
        <source>Axis words found in block when no command or current modal state uses them.</source>
        <translation>Riadok obsahuje slová osí, ktoré žiadny príkaz ani modálny stav nepoužíva.</translation>
    </message>
    <message>
        <source>G2 and G3 arcs require at least one in-plane axis word.</source>
        <translation>Oblúky G2 a G3 vyžadujú aspoň jedno slovo osi v rovine.</translation>
    </message>
    <message>
        <source>Motion command target is invalid.</source>
        <translation>Cieľ pohybového príkazu je neplatný.</translation>
    </message>
    <message>
        <source>Arc radius value is invalid.</source>
        <translation>Polomer oblúka je neplatný.</translation>
    </message>
    <message>
        <source>G2 and G3 arcs require at least one in-plane offset word.</source>
        <translation>Oblúky G2 a G3 vyžadujú aspoň jedno slovo odsadenia v rovine.</translation>
    </message>
    <message>
        <source>Unused value words found in block.</source>
        <translation>Riadok obsahuje nepoužité slová s hodnotou.</translation>
    </message>
    <message>
        <source>G43.1 dynamic tool length offset is not assigned to configured tool length axis.</source>
        <translation>Dynamická korekcia dĺžky nástroja G43.1 nie je priradená k nastavenej osi dĺžky nástroja.</translation>
    </message>
    <message>
        <source>Tool number greater than max supported value.</source>
        <translation>Číslo nástroja je väčšie ako najväčšie podporované.</translation>
    </message>
    <message>
        <source>A code GRBL 1.1 does not document.</source>
        <translation>Kód, ktorý dokumentácia GRBL 1.1 nepozná.</translation>
    </message>
</context>
<context>
    <name>GrblMeaning</name>
    <message>
        <source>expected command letter: a G-code word needs a letter</source>
        <extracomment>The codec&apos;s texts, marked for translation (the same English: lupdate reads these).</extracomment>
        <translation>očakávané písmeno príkazu: slovo G-kódu potrebuje písmeno</translation>
    </message>
    <message>
        <source>bad number format: a word&apos;s value is missing or malformed</source>
        <translation>chybný formát čísla: hodnota slova chýba alebo je chybná</translation>
    </message>
    <message>
        <source>invalid statement: &apos;$&apos; system command not recognised</source>
        <translation>neplatný príkaz: systémový príkaz &apos;$&apos; nerozpoznaný</translation>
    </message>
    <message>
        <source>negative value where a positive one is expected</source>
        <translation>záporná hodnota tam, kde sa čaká kladná</translation>
    </message>
    <message>
        <source>setting disabled: homing is not enabled</source>
        <translation>nastavenie vypnuté: referenčná jazda nie je povolená</translation>
    </message>
    <message>
        <source>step pulse time must be at least 3 microseconds</source>
        <translation>dĺžka krokového impulzu musí byť aspoň 3 mikrosekundy</translation>
    </message>
    <message>
        <source>EEPROM read failed, defaults restored</source>
        <translation>čítanie EEPROM zlyhalo, obnovené predvolené hodnoty</translation>
    </message>
    <message>
        <source>not idle: this &apos;$&apos; command needs the machine idle</source>
        <translation>nie je v pokoji: tento príkaz &apos;$&apos; vyžaduje stroj v pokoji</translation>
    </message>
    <message>
        <source>G-code locked out during alarm or jog</source>
        <translation>G-kód zablokovaný počas alarmu alebo ručného posuvu</translation>
    </message>
    <message>
        <source>soft limits need homing enabled</source>
        <translation>softvérové limity vyžadujú povolenú referenčnú jazdu</translation>
    </message>
    <message>
        <source>line overflow: too many characters in the line, not executed</source>
        <translation>pretečenie riadku: príliš veľa znakov, nevykonané</translation>
    </message>
    <message>
        <source>setting would exceed the maximum step rate</source>
        <translation>nastavenie by prekročilo najvyššiu frekvenciu krokov</translation>
    </message>
    <message>
        <source>safety door open</source>
        <translation>bezpečnostné dvierka otvorené</translation>
    </message>
    <message>
        <source>line length exceeded: build info or startup line too long to store</source>
        <translation>prekročená dĺžka riadku: údaj o zostavení alebo štartovací riadok je príliš dlhý na uloženie</translation>
    </message>
    <message>
        <source>travel exceeded: target beyond the machine&apos;s travel, ignored</source>
        <translation>prekročený pojazd: cieľ mimo pojazdu stroja, ignorované</translation>
    </message>
    <message>
        <source>invalid jog command</source>
        <translation>neplatný príkaz ručného posuvu</translation>
    </message>
    <message>
        <source>laser mode requires PWM output</source>
        <translation>laserový režim vyžaduje výstup PWM</translation>
    </message>
    <message>
        <source>unsupported or invalid G-code command</source>
        <translation>nepodporovaný alebo neplatný príkaz G-kódu</translation>
    </message>
    <message>
        <source>modal group violation: two commands of one modal group in a line</source>
        <translation>porušenie modálnej skupiny: dva príkazy jednej modálnej skupiny v riadku</translation>
    </message>
    <message>
        <source>undefined feed rate</source>
        <translation>nedefinovaný posuv</translation>
    </message>
    <message>
        <source>command requires an integer value</source>
        <translation>príkaz vyžaduje celé číslo</translation>
    </message>
    <message>
        <source>more than one command in the line needs axis words</source>
        <translation>viac ako jeden príkaz v riadku potrebuje slová osí</translation>
    </message>
    <message>
        <source>repeated word in the line</source>
        <translation>opakované slovo v riadku</translation>
    </message>
    <message>
        <source>no axis words for a command that needs them</source>
        <translation>chýbajú slová osí pre príkaz, ktorý ich potrebuje</translation>
    </message>
    <message>
        <source>invalid line number</source>
        <translation>neplatné číslo riadku</translation>
    </message>
    <message>
        <source>command is missing a required value word</source>
        <translation>príkazu chýba povinné slovo s hodnotou</translation>
    </message>
    <message>
        <source>G59.x work coordinate systems are not supported</source>
        <translation>pracovné súradnicové systémy G59.x nie sú podporované</translation>
    </message>
    <message>
        <source>G53 only with G0 and G1</source>
        <translation>G53 len s G0 a G1</translation>
    </message>
    <message>
        <source>axis words that no command uses</source>
        <translation>slová osí, ktoré žiadny príkaz nepoužíva</translation>
    </message>
    <message>
        <source>G2/G3 arcs need at least one in-plane axis word</source>
        <translation>oblúky G2/G3 potrebujú aspoň jedno slovo osi v rovine</translation>
    </message>
    <message>
        <source>motion target is invalid</source>
        <translation>cieľ pohybu je neplatný</translation>
    </message>
    <message>
        <source>arc radius is invalid</source>
        <translation>polomer oblúka je neplatný</translation>
    </message>
    <message>
        <source>G2/G3 arcs need at least one in-plane offset word</source>
        <translation>oblúky G2/G3 potrebujú aspoň jedno slovo posunutia v rovine</translation>
    </message>
    <message>
        <source>unused value words in the line</source>
        <translation>nepoužité slová s hodnotou v riadku</translation>
    </message>
    <message>
        <source>dynamic tool length offset not on the tool length axis</source>
        <translation>dynamická korekcia dĺžky nástroja nie je na osi dĺžky nástroja</translation>
    </message>
    <message>
        <source>tool number greater than supported</source>
        <translation>číslo nástroja väčšie, ako je podporované</translation>
    </message>
    <message>
        <source>hard limit triggered: position likely lost; reset, then home</source>
        <translation>zopol koncový spínač: poloha je pravdepodobne stratená; resetujte, potom vykonajte referenčnú jazdu</translation>
    </message>
    <message>
        <source>soft limit: target beyond the travel; reset, then unlock or home</source>
        <translation>softvérový limit: cieľ mimo pojazdu; resetujte, potom odomknite alebo vykonajte referenčnú jazdu</translation>
    </message>
    <message>
        <source>reset while in motion: position likely lost, re-home</source>
        <translation>reset počas pohybu: poloha je pravdepodobne stratená, vykonajte referenčnú jazdu</translation>
    </message>
    <message>
        <source>probe fail: probe not in the expected initial state</source>
        <translation>chyba sondy: sonda nie je v očakávanom východiskovom stave</translation>
    </message>
    <message>
        <source>probe fail: no contact within the programmed travel</source>
        <translation>chyba sondy: žiadny dotyk v naprogramovanej dráhe</translation>
    </message>
    <message>
        <source>homing fail: the homing cycle was reset</source>
        <translation>chyba referenčnej jazdy: cyklus bol resetovaný</translation>
    </message>
    <message>
        <source>homing fail: safety door opened while homing</source>
        <translation>chyba referenčnej jazdy: počas nej sa otvorili bezpečnostné dvierka</translation>
    </message>
    <message>
        <source>homing fail: pull-off did not clear the limit switch</source>
        <translation>chyba referenčnej jazdy: odjazd neuvoľnil koncový spínač</translation>
    </message>
    <message>
        <source>homing fail: limit switch not found within the search distance</source>
        <translation>chyba referenčnej jazdy: koncový spínač nenájdený v hľadanej vzdialenosti</translation>
    </message>
    <message>
        <source>unknown error {0}</source>
        <translation>neznáma chyba {0}</translation>
    </message>
    <message>
        <source>unknown alarm {0}</source>
        <translation>neznámy alarm {0}</translation>
    </message>
    <message>
        <source>homing fail: the second switch of a dual axis did not trigger after the first</source>
        <translation>chyba referenčnej jazdy: druhý spínač zdvojenej osi nezopol po prvom</translation>
    </message>
</context>
<context>
    <name>GrblSetting</name>
    <message>
        <source>X</source>
        <extracomment>GRBL 1.1h on a 328p: N_AXIS. The most steps a second GRBL 1.1 generates on a 16 MHz board (its documentation). GRBL&apos;s uint8 settings keep one byte. The station&apos;s ceiling for a rate, a resolution or a distance. GRBL prints a setting through a 32-bit integer of thousandths (4 294 967.295 at most): far below that.</extracomment>
        <translation>X</translation>
    </message>
    <message>
        <source>Y</source>
        <translation>Y</translation>
    </message>
    <message>
        <source>Z</source>
        <translation>Z</translation>
    </message>
    <message>
        <source>machine position (off: work position)</source>
        <translation>strojová poloha (bez neho: pracovná poloha)</translation>
    </message>
    <message>
        <source>buffer state (Bf:)</source>
        <translation>stav vyrovnávacích pamätí (Bf:)</translation>
    </message>
    <message>
        <source>the station reads positions in millimetres</source>
        <translation>stanica číta polohy v milimetroch</translation>
    </message>
    <message>
        <source>Step pulse time</source>
        <translation>Dĺžka krokového impulzu</translation>
    </message>
    <message>
        <source>How long each step pulse lasts. The stepper drivers name the least they need; GRBL takes no less than 3 µs.</source>
        <translation>Ako dlho trvá každý krokový impulz. Budiče motorov udávajú najkratší, ktorý potrebujú; GRBL neprijme menej ako 3 µs.</translation>
    </message>
    <message>
        <source>Step idle delay</source>
        <translation>Oneskorenie pred uvoľnením motorov</translation>
    </message>
    <message>
        <source>How long the motors stay powered after a motion ends, so the axes settle before they are let go. 255 keeps them powered.</source>
        <translation>Ako dlho zostanú motory pod prúdom po skončení pohybu, aby sa osi ustálili, kým sa uvoľnia. 255 ich nechá pod prúdom stále.</translation>
    </message>
    <message>
        <source>Step pulse invert</source>
        <translation>Inverzia krokového signálu</translation>
    </message>
    <message>
        <source>Axes whose step signal is inverted, one bit each (X 1, Y 2, Z 4), for drivers that step on the other edge.</source>
        <translation>Osi s obráteným krokovým signálom, každá jeden bit (X 1, Y 2, Z 4): pre budiče, ktoré krokujú na opačnej hrane.</translation>
    </message>
    <message>
        <source>Direction invert</source>
        <translation>Inverzia smeru</translation>
    </message>
    <message>
        <source>Axes that move the other way, one bit each (X 1, Y 2, Z 4): the fix for an axis wired backwards.</source>
        <translation>Osi, ktoré sa pohybujú opačne, každá jeden bit (X 1, Y 2, Z 4): náprava osi zapojenej obrátene.</translation>
    </message>
    <message>
        <source>Invert step enable</source>
        <translation>Inverzia povolenia budičov</translation>
    </message>
    <message>
        <source>Inverts the drivers&apos; enable signal (takes effect after a reset).</source>
        <translation>Obráti signál povolenia budičov (platí po resete).</translation>
    </message>
    <message>
        <source>Invert limit pins</source>
        <translation>Inverzia koncových spínačov</translation>
    </message>
    <message>
        <source>Inverts every limit switch input: for switches that are closed until hit.</source>
        <translation>Obráti všetky vstupy koncových spínačov: pre spínače zopnuté, kým na ne os nenarazí.</translation>
    </message>
    <message>
        <source>Invert probe pin</source>
        <translation>Inverzia sondy</translation>
    </message>
    <message>
        <source>Inverts the probe input.</source>
        <translation>Obráti vstup sondy.</translation>
    </message>
    <message>
        <source>Status report options</source>
        <translation>Obsah stavových hlásení</translation>
    </message>
    <message>
        <source>What a status report carries: value 1 the machine position (else the work position), value 2 the free buffer space.</source>
        <translation>Čo nesie stavové hlásenie: hodnota 1 strojovú polohu (inak pracovnú), hodnota 2 voľné miesto vo vyrovnávacích pamätiach.</translation>
    </message>
    <message>
        <source>Junction deviation</source>
        <translation>Odchýlka v rohoch</translation>
    </message>
    <message>
        <source>How fast the machine may go through a corner between two moves: smaller is slower and gentler.</source>
        <translation>Ako rýchlo smie stroj prejsť rohom medzi dvoma pohybmi: menšia je pomalšia a šetrnejšia.</translation>
    </message>
    <message>
        <source>Arc tolerance</source>
        <translation>Tolerancia oblúkov</translation>
    </message>
    <message>
        <source>How far the short lines GRBL draws an arc with may stray from the arc. Very small values cost speed.</source>
        <translation>Ako ďaleko sa smú krátke úsečky, ktorými GRBL kreslí oblúk, od oblúka odchýliť. Veľmi malé hodnoty stoja rýchlosť.</translation>
    </message>
    <message>
        <source>Report in inches</source>
        <translation>Hlásenia v palcoch</translation>
    </message>
    <message>
        <source>Positions and rates reported in inches instead of millimetres.</source>
        <translation>Polohy a rýchlosti hlásené v palcoch namiesto milimetrov.</translation>
    </message>
    <message>
        <source>Soft limits</source>
        <translation>Softvérové limity</translation>
    </message>
    <message>
        <source>Refuses, with an alarm, any motion past the maximum travel ($130…). Needs homing ($22=1).</source>
        <translation>Odmietne s alarmom každý pohyb za najväčšiu dráhu ($130…). Potrebuje nájazd do východiskovej polohy ($22=1).</translation>
    </message>
    <message>
        <source>Hard limits</source>
        <translation>Koncové spínače</translation>
    </message>
    <message>
        <source>Stops at once with an alarm when a limit switch is hit.</source>
        <translation>Zastaví okamžite s alarmom, keď os narazí na koncový spínač.</translation>
    </message>
    <message>
        <source>Homing cycle</source>
        <translation>Nájazd do východiskovej polohy</translation>
    </message>
    <message>
        <source>Enables homing ($H). Needs a limit switch on every axis; the board then starts in alarm until homed.</source>
        <translation>Povolí nájazd do východiskovej polohy ($H). Potrebuje koncový spínač na každej osi; doska potom štartuje v alarme, kým nenabehne.</translation>
    </message>
    <message>
        <source>Homing direction invert</source>
        <translation>Inverzia smeru nájazdu</translation>
    </message>
    <message>
        <source>Axes that look for their switch in the negative direction, one bit each (X 1, Y 2, Z 4).</source>
        <translation>Osi, ktoré hľadajú svoj spínač v zápornom smere, každá jeden bit (X 1, Y 2, Z 4).</translation>
    </message>
    <message>
        <source>Homing locate feed rate</source>
        <translation>Rýchlosť dohľadania spínača</translation>
    </message>
    <message>
        <source>The slow speed at which homing finds the switch&apos;s exact place.</source>
        <translation>Pomalá rýchlosť, ktorou nájazd nájde presné miesto spínača.</translation>
    </message>
    <message>
        <source>Homing search seek rate</source>
        <translation>Rýchlosť hľadania spínača</translation>
    </message>
    <message>
        <source>The fast speed at which homing first looks for the switch.</source>
        <translation>Rýchla rýchlosť, ktorou nájazd najprv hľadá spínač.</translation>
    </message>
    <message>
        <source>Homing switch debounce</source>
        <translation>Odskok spínača pri nájazde</translation>
    </message>
    <message>
        <source>A pause between the phases of homing while the switch stops bouncing.</source>
        <translation>Prestávka medzi fázami nájazdu, kým spínač prestane zakmitávať.</translation>
    </message>
    <message>
        <source>Homing pull-off</source>
        <translation>Odjazd od spínača</translation>
    </message>
    <message>
        <source>How far homing backs off its switch. Homing fails if the switch is still pressed after it.</source>
        <translation>Ako ďaleko nájazd odíde od spínača. Zlyhá, keď je spínač potom stále zopnutý.</translation>
    </message>
    <message>
        <source>Maximum spindle speed</source>
        <translation>Najväčšie otáčky vretena</translation>
    </message>
    <message>
        <source>The S value that gives full PWM duty (on a servo pen plotter: the pen&apos;s full travel).</source>
        <translation>Hodnota S, ktorá dá plnú striedu PWM (pri plotri so servom: plný zdvih pera).</translation>
    </message>
    <message>
        <source>Minimum spindle speed</source>
        <translation>Najmenšie otáčky vretena</translation>
    </message>
    <message>
        <source>The S value that gives the least PWM duty; below $30.</source>
        <translation>Hodnota S, ktorá dá najmenšiu striedu PWM; pod $30.</translation>
    </message>
    <message>
        <source>Laser mode</source>
        <translation>Laserový režim</translation>
    </message>
    <message>
        <source>Moves go on through changes of S without stopping, as a laser needs; a spindle would need time to change speed.</source>
        <translation>Pohyby pokračujú cez zmeny S bez zastavenia, ako potrebuje laser; vreteno by potrebovalo čas na zmenu otáčok.</translation>
    </message>
    <message>
        <source>{0} resolution</source>
        <translation>{0} rozlíšenie</translation>
    </message>
    <message>
        <source>Steps the axis&apos;s motor makes for one millimetre of travel.</source>
        <translation>Kroky, ktoré motor osi urobí na jeden milimeter dráhy.</translation>
    </message>
    <message>
        <source>{0} maximum rate</source>
        <translation>{0} najväčšia rýchlosť</translation>
    </message>
    <message>
        <source>The axis&apos;s top speed; rapid moves (G0) run at it.</source>
        <translation>Najvyššia rýchlosť osi; rýchloposuvy (G0) idú ňou.</translation>
    </message>
    <message>
        <source>{0} acceleration</source>
        <translation>{0} zrýchlenie</translation>
    </message>
    <message>
        <source>How fast the axis may speed up and slow down, planned so that the motor loses no steps.</source>
        <translation>Ako rýchlo smie os zrýchľovať a brzdiť, plánované tak, aby motor nestratil kroky.</translation>
    </message>
    <message>
        <source>{0} maximum travel</source>
        <translation>{0} najväčšia dráha</translation>
    </message>
    <message>
        <source>How far the axis can travel from its home switch: the space soft limits keep to, and how far homing searches.</source>
        <translation>Ako ďaleko môže os dôjsť od svojho východiskového spínača: priestor, ktorý strážia softvérové limity, a kam až hľadá nájazd.</translation>
    </message>
    <message>
        <source>$20 (soft limits) needs homing: $22=1</source>
        <extracomment>Every setting GRBL 1.1h lists in ``$$``, in its order.</extracomment>
        <translation>$20 (softvérové limity) potrebuje nájazd do východiskovej polohy: $22=1</translation>
    </message>
    <message>
        <source>$31 (minimum spindle speed) must be below $30</source>
        <translation>$31 (najmenšie otáčky vretena) musí byť pod $30</translation>
    </message>
    <message>
        <source>{0}: at most the mechanical travel, {1} mm</source>
        <translation>{0}: najviac mechanická dráha, {1} mm</translation>
    </message>
    <message>
        <source>{0} and {1}: {2} steps/s, more than GRBL steps ({3})</source>
        <translation>{0} a {1}: {2} krokov/s, viac, než GRBL zvládne ({3})</translation>
    </message>
</context>
<context>
    <name>HandZeroing</name>
    <message>
        <source>Not released: {0}</source>
        <extracomment>The motors were released for zeroing by hand and nothing was sent since.</extracomment>
        <translation>Neuvoľnené: {0}</translation>
    </message>
    <message>
        <source>Motors released: turn the axes by hand to the zero, then Zero here</source>
        <translation>Motory uvoľnené: otočte osi rukou do nuly, potom Nula tu</translation>
    </message>
    <message>
        <source>Not zeroed: release the motors first</source>
        <translation>Nevynulované: najprv uvoľnite motory</translation>
    </message>
    <message>
        <source>Not zeroed: {0}</source>
        <translation>Nevynulované: {0}</translation>
    </message>
    <message>
        <source>Zeroed by hand: X is the board radius, {0} mm</source>
        <translation>Vynulované ručne: X je polomer dosky, {0} mm</translation>
    </message>
</context>
<context>
    <name>InfoPanel</name>
    <message>
        <source>Battery charge and voltage</source>
        <extracomment>The LED ring&apos;s colours, as drawn beside its state; blinking states say so in words. Status texts worth a colour; the rest stay in the normal text colour. The machine position, shown beside the work position while they differ.</extracomment>
        <translation>Nabitie a napätie batérie</translation>
    </message>
    <message>
        <source>Link {0}</source>
        <translation>Spojenie: {0}</translation>
    </message>
    <message>
        <source>Last known — the link is {0}</source>
        <translation>Posledná známa hodnota — spojenie: {0}</translation>
    </message>
    <message>
        <source>battery —</source>
        <translation>batéria —</translation>
    </message>
    <message>
        <source>battery {0} %</source>
        <translation>batéria {0} %</translation>
    </message>
    <message>
        <source>board —</source>
        <translation>doska —</translation>
    </message>
    <message>
        <source>board {0} °C</source>
        <translation>doska {0} °C</translation>
    </message>
    <message>
        <source>LED ring: {0}</source>
        <translation>LED kruh: {0}</translation>
    </message>
    <message>
        <source>The stage&apos;s LED ring as its device flags say it is lit</source>
        <translation>LED kruh stolíka, ako svieti podľa jeho stavových príznakov</translation>
    </message>
    <message>
        <source>red</source>
        <translation>červená</translation>
    </message>
    <message>
        <source>red, blinking fast</source>
        <translation>červená, rýchlo bliká</translation>
    </message>
    <message>
        <source>green</source>
        <translation>zelená</translation>
    </message>
    <message>
        <source>blue, blinking slowly</source>
        <translation>modrá, pomaly bliká</translation>
    </message>
    <message>
        <source>blue</source>
        <translation>modrá</translation>
    </message>
    <message>
        <source>off</source>
        <translation>nesvieti</translation>
    </message>
    <message>
        <source>Charger connected</source>
        <translation>Nabíjačka pripojená</translation>
    </message>
    <message>
        <source>Battery low</source>
        <translation>Batéria takmer vybitá</translation>
    </message>
    <message>
        <source>Standby: the stage is asleep</source>
        <translation>Pohotovosť: stolík spí</translation>
    </message>
    <message>
        <source>Pairing: waiting for a host</source>
        <translation>Párovanie: čaká na hostiteľa</translation>
    </message>
    <message>
        <source>Talking to this station</source>
        <translation>Komunikuje s touto stanicou</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Vypnuté</translation>
    </message>
    <message>
        <source>charger connected</source>
        <translation>pripojená nabíjačka</translation>
    </message>
    <message>
        <source>USB connected</source>
        <translation>pripojené USB</translation>
    </message>
    <message>
        <source>battery low</source>
        <translation>slabá batéria</translation>
    </message>
    <message>
        <source>machine {0}</source>
        <translation>stroj {0}</translation>
    </message>
    <message>
        <source>Machine position; the figure on the left is the work position (G92 work offset {0})</source>
        <translation>Poloha stroja; údaj vľavo je pracovná poloha (pracovné posunutie G92 {0})</translation>
    </message>
</context>
<context>
    <name>JobFile</name>
    <message>
        <source>{0}: {1} has no diameter: its {2} hole(s) are not drilled (give the tool a diameter in the file)</source>
        <extracomment>Diameters closer than this (mm) are the same bit. Tools whose holes are not drilled (no diameter). What the operator is told: each duplicate and each tool without a diameter.</extracomment>
        <translation>{0}: {1} nemá priemer: jeho otvory ({2}) sa nevŕtajú (doplňte nástroju priemer v súbore)</translation>
    </message>
    <message>
        <source>{0}: {1} is {2:.2f} mm like {3}: its {4} hole(s) are drilled with {3}&apos;s bit, no change</source>
        <translation>{0}: {1} má {2:.2f} mm ako {3}: jeho otvory ({4}) sa vŕtajú vrtákom {3}, bez výmeny</translation>
    </message>
    <message>
        <source>no &apos;Units : 1/10000 Inch&apos; line: not an EAGLE .dri</source>
        <extracomment>The highest tool number a drill file may use (Excellon writes two or three digits). The most holes (slot ends counted) a drill file may ask for, repeats (``R…``) included: boards have tens to a few thousand holes; 50 000 (the benchmark&apos;s board) still checks in seconds, where a repeat count of nine digits made gerbonara build holes until memory ran out.</extracomment>
        <translation>chýba riadok „Units : 1/10000 Inch“: nejde o .dri z EAGLE</translation>
    </message>
    <message>
        <source>its drill file {0} is missing</source>
        <translation>chýba k nemu vŕtací súbor {0}</translation>
    </message>
    <message>
        <source>{0}… ({1} digits)</source>
        <translation>{0}… ({1} číslic)</translation>
    </message>
    <message>
        <source>tool number T{0} is above T{1}</source>
        <translation>číslo nástroja T{0} je nad T{1}</translation>
    </message>
    <message>
        <source>tool diameter {0} is not a number</source>
        <translation>priemer nástroja {0} nie je číslo</translation>
    </message>
    <message>
        <source>tool diameter of T{0:02d} is {1:g}: a drill must be wider than 0</source>
        <translation>priemer T{0:02d} je {1:g}: vrták musí mať priemer väčší ako 0</translation>
    </message>
    <message>
        <source>routed arcs (G02/G03) cannot be drilled</source>
        <translation>frézované oblúky (G02/G03) sa nedajú vŕtať</translation>
    </message>
    <message>
        <source>G85 slot without an end point: nothing to cut to</source>
        <translation>drážka G85 bez koncového bodu: nie je kam frézovať</translation>
    </message>
    <message>
        <source>no unit in the file; inch assumed, as the Excellon step is</source>
        <translation>súbor neuvádza jednotky; predpokladajú sa palce, rovnako ako pri kroku Excellonu</translation>
    </message>
    <message>
        <source>not an Excellon statement: {0}</source>
        <translation>nejde o príkaz Excellonu: {0}</translation>
    </message>
    <message>
        <source>unknown tool: {0} is not defined</source>
        <translation>neznámy nástroj: {0} nie je definovaný</translation>
    </message>
    <message>
        <source>integer coordinates, but the file gives no number format (metric)</source>
        <translation>celočíselné súradnice, ale súbor neuvádza formát čísel (metrický)</translation>
    </message>
    <message>
        <source>the Excellon reader cannot read {0} ({1})</source>
        <translation>čítačka Excellonu nedokáže prečítať {0} ({1})</translation>
    </message>
    <message>
        <source>coordinates before any tool is selected: {0}</source>
        <translation>súradnice pred výberom nástroja: {0}</translation>
    </message>
    <message>
        <source>coordinates before the header: {0}</source>
        <translation>súradnice pred hlavičkou: {0}</translation>
    </message>
    <message>
        <source>coordinates after the end of the program: {0}</source>
        <translation>súradnice za koncom programu: {0}</translation>
    </message>
    <message>
        <source>a coordinate too large for a number</source>
        <translation>súradnica je príliš veľká</translation>
    </message>
    <message>
        <source>no holes in the file: nothing to drill</source>
        <translation>v súbore nie sú žiadne otvory: nie je čo vŕtať</translation>
    </message>
    <message>
        <source>{0} of {1} is not in the tool list</source>
        <translation>{0} zo súboru {1} nie je v zozname nástrojov</translation>
    </message>
    <message>
        <source>{0} is {1:.3f} mm here but {2:.3f} mm in {3}</source>
        <translation>{0} má tu {1:.3f} mm, ale v {3} {2:.3f} mm</translation>
    </message>
    <message>
        <source>{0} drills {1} holes here but {2} in {3}: the files do not belong together</source>
        <translation>{0} tu vŕta {1} otvorov, ale v {3} {2}: súbory k sebe nepatria</translation>
    </message>
    <message>
        <source> (also {0})</source>
        <extracomment>Duplicate tools and tools without a diameter, &quot;file:line: text&quot; (see bits.py).</extracomment>
        <translation> (aj {0})</translation>
    </message>
    <message>
        <source>insert {0}, {1:.2f} mm, {2} hole{3}</source>
        <translation>vložte {0}, {1:.2f} mm, {2} otvor{3}</translation>
    </message>
    <message>
        <source>insert {0}, {1:.2f} mm, {2} holes{3}</source>
        <translation>vložte {0}, {1:.2f} mm, otvorov: {2}{3}</translation>
    </message>
    <message>
        <source>pen for {0}, {1:.2f} mm, {2} hole{3}</source>
        <translation>pero pre {0}, {1:.2f} mm, {2} otvor{3}</translation>
    </message>
    <message>
        <source>pen for {0}, {1:.2f} mm, {2} holes{3}</source>
        <translation>pero pre {0}, {1:.2f} mm, otvorov: {2}{3}</translation>
    </message>
    <message>
        <source>travel between holes: {0:.1f} mm in file order, {1:.1f} mm optimised ({2:.1f} mm saved)</source>
        <translation>pojazd medzi otvormi: {0:.1f} mm v poradí súboru, {1:.1f} mm po optimalizácii (ušetrené {2:.1f} mm)</translation>
    </message>
    <message>
        <source>: warning: </source>
        <translation>: upozornenie: </translation>
    </message>
    <message>
        <source>arc target invalid: an R arc needs distinct ends (error:33): {0}</source>
        <extracomment>Largest chord error of a flattened arc (mm, GRBL&apos;s $12) and the fewest segments one gets. The most chords one arc becomes; an arc needing more is refused. The most inner vertices all the arcs of one file become. GRBL&apos;s arc definition check: the end&apos;s radius may differ from the start&apos;s by this much… …and beyond it by at most 0.5 mm and 0.1 % of the radius (gcode.c).</extracomment>
        <translation>neplatný cieľ oblúka: oblúk R potrebuje rôzne koncové body (error:33): {0}</translation>
    </message>
    <message>
        <source>arc radius error: R {0:g} mm is less than half the chord {1:g} mm (error:34): {2}</source>
        <translation>chyba polomeru oblúka: R {0:g} mm je menší ako polovica tetivy {1:g} mm (error:34): {2}</translation>
    </message>
    <message>
        <source>arc without offsets: it needs I/J or R (error:35): {0}</source>
        <translation>oblúk bez stredu: potrebuje I/J alebo R (error:35): {0}</translation>
    </message>
    <message>
        <source>arc coordinates too large to draw: {0}</source>
        <translation>súradnice oblúka sú príliš veľké na vykreslenie: {0}</translation>
    </message>
    <message>
        <source>arc end not on its circle: radius {0:.4g} mm at the start, {1:.4g} mm at the end (error:33): {2}</source>
        <translation>koniec oblúka neleží na jeho kružnici: polomer {0:.4g} mm na začiatku, {1:.4g} mm na konci (error:33): {2}</translation>
    </message>
    <message>
        <source>arc too long: {0:.4g} m of radius {1:.4g} mm needs {2} chords at {3:g} mm (at most {4}); no machine&apos;s travel holds it</source>
        <translation>oblúk je príliš dlhý: {0:.4g} m s polomerom {1:.4g} mm vyžaduje {2} úsečiek pri {3:g} mm (najviac {4}); taký pojazd nemá žiadny stroj</translation>
    </message>
    <message>
        <source>arcs too many: the file&apos;s arcs need more than {0:,} vertices at {1:g} mm</source>
        <translation>príliš veľa oblúkov: oblúky v súbore vyžadujú viac ako {0:,} vrcholov pri {1:g} mm</translation>
    </message>
    <message>
        <source>more than 16 axes</source>
        <extracomment>Pen lines sent as the profile&apos;s own pen command.</extracomment>
        <translation>viac ako 16 osí</translation>
    </message>
    <message>
        <source>no G-code to send in the file</source>
        <translation>v súbore nie je žiadny G-kód na odoslanie</translation>
    </message>
    <message>
        <source>named parameters/expressions are not G-code this machine runs</source>
        <extracomment>Translated where it is used (a parameter line is refused in the operator&apos;s language).</extracomment>
        <translation>pomenované parametre a výrazy nie sú G-kód, ktorý tento stroj vykonáva</translation>
    </message>
    <message>
        <source>the {0}</source>
        <extracomment>Words GRBL refuses negative (error:4). GRBL&apos;s largest tool number (error:38) and line number (error:27). Refusals collected from one file before reading stops (the first ones are what matter). Lines go to the board compact (``GcodeSettings.compact_lines``): the line limit is the compact line&apos;s, what the board&apos;s line buffer really holds. A GRBL board (it takes ``$J``): its error codes are GRBL 1.1&apos;s own.</extracomment>
        <translation>stroj {0}</translation>
    </message>
    <message>
        <source>this machine</source>
        <translation>tento stroj</translation>
    </message>
    <message>
        <source>machine</source>
        <translation>stroj</translation>
    </message>
    <message>
        <source>word repeated: {0} twice (error:25): {1}</source>
        <translation>opakované slovo: {0} dvakrát (error:25): {1}</translation>
    </message>
    <message>
        <source>max value exceeded: T{0} above T{1} (error:38)</source>
        <translation>prekročená najväčšia hodnota: T{0} nad T{1} (error:38)</translation>
    </message>
    <message>
        <source>negative value: {0} cannot be negative (error:4)</source>
        <translation>záporná hodnota: {0} nesmie byť záporné (error:4)</translation>
    </message>
    <message>
        <source>modal group violation: two motion words (error:21): {0}</source>
        <translation>porušenie modálnej skupiny: dva príkazy pohybu (error:21): {0}</translation>
    </message>
    <message>
        <source>invalid line number: N{0} above N{1} (error:27)</source>
        <translation>neplatné číslo riadku: N{0} nad N{1} (error:27)</translation>
    </message>
    <message>
        <source>M{0}: paused</source>
        <translation>M{0}: pozastavené</translation>
    </message>
    <message>
        <source>{0} cannot execute {1}</source>
        <extracomment>A bare ``G92`` makes the current position the origin (the CoreXY plotter&apos;s firmware); GRBL refuses it (error:26). A G4 with P was read (its unit is worth a note where it is seconds). Inner arc vertices the file&apos;s arcs may still have (arcs.MAX_ARC_VERTICES in all). Lines whose operations depend on nothing but their text (pen commands, dwells): the pen state they set, their operations and the machine&apos;s objections. Lines refused at load (GRBL&apos;s errors, malformed text), in file order. Columns whose positions count from wherever the machine stands when the job starts (a G91 move or a G92 before the file set them): taken here as from 0.</extracomment>
        <translation>{0} nevie vykonať {1}</translation>
    </message>
    <message>
        <source>? not sent: the station asks for the status itself</source>
        <translation>? neodoslané: stanica sa na stav pýta sama</translation>
    </message>
    <message>
        <source>{0} ({1}) is a real-time command, not a line of a job</source>
        <translation>{0} ({1}) je príkaz reálneho času, nie riadok úlohy</translation>
    </message>
    <message>
        <source>arc without axis words (error:26): {0}</source>
        <translation>oblúk bez súradníc osí (error:26): {0}</translation>
    </message>
    <message>
        <source>feed rate undefined: {0} before any F sets one (error:22): {1}</source>
        <translation>posuv nie je zadaný: {0} skôr, než ho nastaví F (error:22): {1}</translation>
    </message>
    <message>
        <source>{0} is not ASCII</source>
        <translation>{0} nie je ASCII</translation>
    </message>
    <message>
        <source>{0} characters; a line holds at most {1}</source>
        <translation>{0} znakov; riadok pojme najviac {1}</translation>
    </message>
    <message>
        <source>{0} has no {1} axis</source>
        <translation>{0} nemá os {1}</translation>
    </message>
    <message>
        <source>not sent: {0} ({1})</source>
        <translation>neodoslané: {0} ({1})</translation>
    </message>
    <message>
        <source>{0} pen line sent as the {1}&apos;s {2}/{3}</source>
        <translation>riadky pera odoslané ako {2}/{3} stroja {1}: {0}</translation>
    </message>
    <message>
        <source>{0} pen lines sent as the {1}&apos;s {2}/{3}</source>
        <translation>riadky pera odoslané ako {2}/{3} stroja {1}: {0}</translation>
    </message>
    <message>
        <source>pen servo {0}: S{1:g} lowers the pen, S{2:g} lifts it</source>
        <translation>servo pera {0}: S{1:g} pero spúšťa, S{2:g} dvíha</translation>
    </message>
    <message>
        <source>Z heights are the pen: above 0 up, 0 or below down</source>
        <translation>výška Z je pero: nad 0 hore, 0 a nižšie dole</translation>
    </message>
    <message>
        <source>Z not sent on {0} line(s): Z is the {1}&apos;s pen and this file&apos;s Z never lifts it</source>
        <translation>Z neodoslané na riadkoch: {0}; Z je pero stroja {1} a Z v tomto súbore ho nikdy nezdvíha</translation>
    </message>
    <message>
        <source>{0} G21 line not sent: the machine works in mm</source>
        <translation>riadky G21 neodoslané: {0}; stroj pracuje v mm</translation>
    </message>
    <message>
        <source>{0} G21 lines not sent: the machine works in mm</source>
        <translation>riadky G21 neodoslané: {0}; stroj pracuje v mm</translation>
    </message>
    <message>
        <source>G4 P is seconds on the {0} (GRBL): {1} dwell(s) wait {2} in all; a file written for milliseconds (Marlin, Inkscape Unicorn) waits a thousand times too long here</source>
        <translation>G4 P sú na stroji {0} (GRBL) sekundy: prestávky ({1}) čakajú spolu {2}; súbor písaný pre milisekundy (Marlin, Inkscape Unicorn) tu čaká tisíckrát dlhšie</translation>
    </message>
    <message>
        <source>this plotter ignores F ({0} line(s) carry it): G0 and G1 run alike, the speed is set by M98 &lt;µs&gt; (the step interval, {1:g} µs at power-on)</source>
        <translation>tento plotter F nepoužíva (nesie ho {0} riadkov): G0 a G1 idú rovnako, rýchlosť nastavuje M98 &lt;µs&gt; (interval medzi krokmi, po zapnutí {1:g} µs)</translation>
    </message>
    <message>
        <source>no pen commands: G0 moves are shown as travel, G1/G2/G3 as work</source>
        <translation>žiadne príkazy pera: pohyby G0 sa zobrazujú ako prejazd, G1/G2/G3 ako práca</translation>
    </message>
    <message>
        <source> and {0} more</source>
        <translation> a ďalších {0}</translation>
    </message>
    <message>
        <source>skipped 1 line: {0} (line {1})</source>
        <translation>preskočený 1 riadok: {0} (riadok {1})</translation>
    </message>
    <message>
        <source>skipped {0} line(s): {1} (lines {2}{3})</source>
        <translation>preskočené riadky: {0}: {1} (riadky {2}{3})</translation>
    </message>
    <message>
        <source>could not split the file into lines</source>
        <extracomment>One record per line: group 1 is the G0/G1 digit of a plain move (a comment may follow), empty for any other line. Plain lines read in one call (regex, numpy): short enough that the window, waiting for the interpreter lock meanwhile, is not kept waiting long. FAST_LINE on the file&apos;s UTF-8 bytes (the pattern is ASCII: the same lines match).</extracomment>
        <translation>súbor sa nedal rozdeliť na riadky</translation>
    </message>
    <message>
        <source>could not read the coordinates</source>
        <translation>súradnice sa nedali prečítať</translation>
    </message>
    <message>
        <source>status query</source>
        <extracomment>The longest line a board takes, without its line end (docs/protocols.md §4: 80 bytes). A word whose number is written with an exponent (``X1e308``): G-code reads it as two words. ``M98 800`` / ``M99 90``: the CoreXY plotter&apos;s step interval and servo level (docs/protocols.md §4.5), the only codes a bare value (a number with no letter) follows. A bare value as a file may write it: unsigned, a digit first. Their names are translated where they are shown.</extracomment>
        <translation>dopyt na stav</translation>
    </message>
    <message>
        <source>feed hold</source>
        <translation>pozastavenie posuvu</translation>
    </message>
    <message>
        <source>cycle start</source>
        <translation>štart cyklu</translation>
    </message>
    <message>
        <source>soft reset</source>
        <translation>softvérový reset</translation>
    </message>
    <message>
        <source>malformed G-code at {0} in {1}</source>
        <extracomment>The cached tokenisations (per distinct line text) stop growing here: repeated lines (pen commands, dwells) are what the cache is for.</extracomment>
        <translation>chybný G-kód pri {0} v {1}</translation>
    </message>
    <message>
        <source>continue when ready</source>
        <translation>pokračujte, keď budete pripravení</translation>
    </message>
    <message>
        <source>expected {0} numbers, found {1}</source>
        <translation>očakávaných čísel: {0}, nájdených: {1}</translation>
    </message>
    <message>
        <source>not a number in {0}</source>
        <translation>nie je číslo v {0}</translation>
    </message>
    <message>
        <source>not a finite number in {0}</source>
        <translation>nie je konečné číslo v {0}</translation>
    </message>
    <message>
        <source>no positions in the file</source>
        <translation>v súbore nie sú žiadne polohy</translation>
    </message>
    <message>
        <source>turn beside it</source>
        <extracomment>The winder&apos;s axes: base angle (deg), tool radius (mm), tool along the drill axis (mm). The nail each operation serves (-1: none). The sequence entry each operation winds to (-1: drill phase). The axis each MOVE sets (0 A, 1 X, 2 Z; -1 for other operations) and its value. Index of the operator&apos;s WAIT between drilling and winding. Model seconds on the profile it was built for (None without a profile). The largest outer radius (each nail&apos;s own is its radius plus ``needle_out_mm``). The dwells at the holes&apos; bottoms (``G4`` operations) and how long each is. Operations read at a time by :meth:`StringArtProgram.column_after`. Entries computed at a time: the temporaries of a chunk stay a few megabytes however long the list (a whole 2-million-entry list at once took about 150 MB of them). Translated once per program (an operation is made each time it is read).</extracomment>
        <translation>natočiť vedľa neho</translation>
    </message>
    <message>
        <source>needle out</source>
        <translation>ihla von</translation>
    </message>
    <message>
        <source>round the nail</source>
        <translation>okolo klinca</translation>
    </message>
    <message>
        <source>needle in</source>
        <translation>ihla dnu</translation>
    </message>
    <message>
        <source>nail {0} ({1}/{2}): {3}</source>
        <translation>klinec {0} ({1}/{2}): {3}</translation>
    </message>
    <message>
        <source>a board of {0:g} cm radius leaves no room for the needle {1:g} mm inside the nails</source>
        <translation>doska s polomerom {0:g} cm nenecháva miesto pre ihlu {1:g} mm vnútri klincov</translation>
    </message>
    <message>
        <source>drill phase: {0} nails</source>
        <translation>vŕtanie: klincov {0}</translation>
    </message>
    <message>
        <source>{0:g} mm above the board</source>
        <translation>{0:g} mm nad doskou</translation>
    </message>
    <message>
        <source>drill {0}</source>
        <translation>vrták {0}</translation>
    </message>
    <message>
        <source>drill nail {0}</source>
        <translation>vŕtanie pre klinec {0}</translation>
    </message>
    <message>
        <source>{0}: turn the base</source>
        <translation>{0}: natočiť základňu</translation>
    </message>
    <message>
        <source>{0}: tool to its radius</source>
        <translation>{0}: nástroj na jeho polomer</translation>
    </message>
    <message>
        <source>{0}: drill</source>
        <translation>{0}: vŕtať</translation>
    </message>
    <message>
        <source>{0}: at the bottom</source>
        <translation>{0}: na dne</translation>
    </message>
    <message>
        <source>{0}: back {1}</source>
        <translation>{0}: späť {1}</translation>
    </message>
    <message>
        <source>back to nail 0</source>
        <translation>späť ku klincu 0</translation>
    </message>
    <message>
        <source>winding: {0} connections</source>
        <translation>navíjanie: spojov {0}</translation>
    </message>
    <message>
        <source>drivers off while waiting</source>
        <translation>budiče vypnuté počas čakania</translation>
    </message>
    <message>
        <source>Insert the nails, tie the thread to nail {0}</source>
        <translation>Vložte klince, priviažte niť ku klincu {0}</translation>
    </message>
    <message>
        <source>start at nail {0}</source>
        <translation>začiatok pri klinci {0}</translation>
    </message>
    <message>
        <source>{0}: needle out</source>
        <translation>{0}: ihla von</translation>
    </message>
    <message>
        <source>{0}: turn</source>
        <translation>{0}: natočiť</translation>
    </message>
    <message>
        <source>{0}: needle in</source>
        <translation>{0}: ihla dnu</translation>
    </message>
    <message>
        <source>{0}: turn back</source>
        <translation>{0}: natočiť späť</translation>
    </message>
    <message>
        <source>drill driver off while winding</source>
        <translation>budič vŕtačky vypnutý počas navíjania</translation>
    </message>
    <message>
        <source>winding done: tie the thread off at nail {0}</source>
        <translation>navíjanie hotové: priviažte niť na klinci {0}</translation>
    </message>
    <message>
        <source>a string-art job needs the winder&apos;s axes A, X and Z (profile string-art); this machine has {0}</source>
        <translation>úloha string-art potrebuje osi navíjačky A, X a Z (profil string-art); tento stroj má {0}</translation>
    </message>
    <message>
        <source>none</source>
        <translation>žiadne</translation>
    </message>
    <message>
        <source>circle</source>
        <extracomment>The most nails a board may have (boards are wound with a few hundred). The most sides of a polygonal board. The largest board radius, in cm (no winder turns a board of 10 m). The most nail indices in a sequence. A nail index with more digits is out of range on any board (MAX_NAILS has five).</extracomment>
        <translation>kruhu</translation>
    </message>
    <message>
        <source>{0}-gon</source>
        <translation>{0}-uholníku</translation>
    </message>
    <message>
        <source>{0} nails on a {1} of {2:g} cm radius, {3} connections, thread {4:.1f} m</source>
        <extracomment>The line of each sequence entry in ``poradi_path`` (1-based; int32 for long lists). The line of each ``param.txt`` key (absent: supplied by the operator).</extracomment>
        <translation>klincov: {0} na {1} s polomerom {2:g} cm, spojov: {3}, niť {4:.1f} m</translation>
    </message>
    <message>
        <source>, about {0}</source>
        <translation>, asi {0}</translation>
    </message>
    <message>
        <source>a nail list without {0}: give the board (shape, at least {1} nails, radius) to load its {2} entries</source>
        <translation>zoznam klincov bez {0}: zadajte dosku (tvar, najmenej {1} klincov, polomer), aby sa dali načítať jeho položky ({2})</translation>
    </message>
    <message>
        <source>expected &apos;key = value&apos;, found {0}</source>
        <translation>očakávané „kľúč = hodnota“, nájdené {0}</translation>
    </message>
    <message>
        <source>{0} given twice (first on line {1})</source>
        <translation>{0} zadané dvakrát (prvýkrát na riadku {1})</translation>
    </message>
    <message>
        <source>{0} = {1} is not a number</source>
        <translation>{0} = {1} nie je číslo</translation>
    </message>
    <message>
        <source>{0} = {1} is too large</source>
        <translation>{0} = {1} je príliš veľké</translation>
    </message>
    <message>
        <source>{0} = {1} is not a whole number</source>
        <translation>{0} = {1} nie je celé číslo</translation>
    </message>
    <message>
        <source>no &apos;{0} = …&apos; line (line 0: missing, not wrong)</source>
        <translation>chýba riadok „{0} = …“ (riadok 0: chýba, nie je chybný)</translation>
    </message>
    <message>
        <source>tvar = {0}: a polygon has at most {1} sides</source>
        <translation>tvar = {0}: mnohouholník má najviac {1} strán</translation>
    </message>
    <message>
        <source>tvar = {0}: the shape must be 0 (a circle) or 3 or more (a regular polygon)</source>
        <translation>tvar = {0}: tvar musí byť 0 (kruh) alebo 3 a viac (pravidelný mnohouholník)</translation>
    </message>
    <message>
        <source>pocet_hrebiku = {0}: a board has at most {1} nails</source>
        <translation>pocet_hrebiku = {0}: doska má najviac {1} klincov</translation>
    </message>
    <message>
        <source>pocet_hrebiku = {0}: a board needs at least {1} nails</source>
        <translation>pocet_hrebiku = {0}: doska potrebuje najmenej {1} klincov</translation>
    </message>
    <message>
        <source>polomer_matrice = {0:g} cm: a board&apos;s radius is at most {1}</source>
        <translation>polomer_matrice = {0:g} cm: polomer dosky je najviac {1}</translation>
    </message>
    <message>
        <source>polomer_matrice = {0:g} cm: the nails sit {1:g} cm inside the edge, so the radius must be larger than {1:g} cm</source>
        <translation>polomer_matrice = {0:g} cm: klince sú {1:g} cm od okraja, polomer preto musí byť väčší ako {1:g} cm</translation>
    </message>
    <message>
        <source>number {0} of the file: {1} is not a whole number</source>
        <extracomment>The sequence as int64 (what numpy reads; the tuple is made from it). Values converted between numpy and Python at a time: one conversion of millions holds the interpreter lock throughout (a tenth of a second), and the GUI thread waits for it. Byte classes of a nail list: separators, digits, signs, anything else.</extracomment>
        <translation>číslo {0} v súbore: {1} nie je celé číslo</translation>
    </message>
    <message>
        <source>no nail indices in the file</source>
        <translation>v súbore nie sú žiadne čísla klincov</translation>
    </message>
    <message>
        <source>the count of the file has {1} digits: out of range on any board (at most {2} nails, {3} entries)</source>
        <translation>počet v súbore má {1} číslic: mimo rozsahu akejkoľvek dosky (najviac {2} klincov, {3} položiek)</translation>
    </message>
    <message>
        <source>number {0} of the file has {1} digits: out of range on any board (at most {2} nails, {3} entries)</source>
        <translation>číslo {0} v súbore má {1} číslic: mimo rozsahu akejkoľvek dosky (najviac {2} klincov, {3} položiek)</translation>
    </message>
    <message>
        <source>more than {0} nail indices</source>
        <translation>viac ako {0} čísel klincov</translation>
    </message>
    <message>
        <source>could not read the nail indices</source>
        <translation>čísla klincov sa nedali prečítať</translation>
    </message>
    <message>
        <source>the count says {0} nail indices, but {1} follow</source>
        <translation>počet uvádza {0} čísel klincov, ale nasleduje {1}</translation>
    </message>
    <message>
        <source>fewer than two nails: nothing to wind</source>
        <translation>menej ako dva klince: nie je čo navíjať</translation>
    </message>
    <message>
        <source> ({0} more out of range)</source>
        <translation> (mimo rozsahu sú ešte ďalšie: {0})</translation>
    </message>
    <message>
        <source>entry {0}: nail {1} is out of range 0…{2}{3}</source>
        <translation>položka {0}: klinec {1} je mimo rozsahu 0…{2}{3}</translation>
    </message>
    <message>
        <source>entries {0} and {1}: nail {2} twice in a row (a thread to itself)</source>
        <translation>položky {0} a {1}: klinec {2} dvakrát za sebou (niť sama k sebe)</translation>
    </message>
    <message>
        <source>the board entered: {0}</source>
        <translation>zadaná doska: {0}</translation>
    </message>
    <message>
        <source>no {0} beside it (the nail order)</source>
        <translation>vedľa neho chýba {0} (poradie klincov)</translation>
    </message>
    <message>
        <source>which format? {0}: {1} (choose one: {2})</source>
        <extracomment>Drill files: prompt the bits smallest first instead of in the file&apos;s tool order. Drill files: every hole with the one bit in the spindle, no bit-change prompt (the original drill&apos;s way; a profile&apos;s ``[drill] one_bit``, FIDELITY S2-40). Drill files: what the teacher&apos;s Excellon step makes of their coordinates (its ratio to 1/10000 inch), and per axis name the ratio of the teacher&apos;s microsteps a mm to the profile&apos;s, every job&apos;s (FIDELITY S2-42). 1: the profile&apos;s constants. G-code: pen lines of another flavour are sent as the machine&apos;s own pen commands. G-code: lines the machine cannot execute become comments instead of refusing the job. G-code: the machine&apos;s repertoire and pen conventions (None: a GRBL board). G-code: the machine&apos;s name in refusals (&quot;the CoreXY pen plotter cannot execute M18&quot;). String-art nail lists without a param.txt: the board the operator gave (NeedsNailCount). The job type&apos;s key when the operator chose it (an ambiguous file); None: detected. Reads ``path`` for a machine with these axis names; raises JobFileError with file:line. Whether the first few kilobytes of a file look like this loader&apos;s job type. The short name ``--format`` takes and a chosen format is stored as.</extracomment>
        <translation>ktorý formát? {0}: {1} (vyberte jeden: {2})</translation>
    </message>
    <message>
        <source> or </source>
        <translation> alebo </translation>
    </message>
    <message>
        <source>the file is empty</source>
        <extracomment>Lower-case extension (with the dot) → loader; the dock&apos;s first choice. Every registered job type in registration order: file-dialog filters and sniffing.</extracomment>
        <translation>súbor je prázdny</translation>
    </message>
    <message>
        <source>its content fits several job types</source>
        <translation>obsah zodpovedá viacerým typom úloh</translation>
    </message>
    <message>
        <source>its content fits no {0} job type</source>
        <translation>obsah nezodpovedá žiadnemu typu úlohy {0}</translation>
    </message>
    <message>
        <source>not a job file this station knows (unknown type)</source>
        <translation>nejde o súbor úlohy, ktorý stanica pozná (neznámy typ)</translation>
    </message>
    <message>
        <source>teaching: microsteps a mm changed, the job lands x {0} of its size</source>
        <translation>výučba: mikrokroky na mm zmenené, úloha dopadne v {0} násobku svojej veľkosti</translation>
    </message>
    <message>
        <source>a drill job needs a machine with X and Y axes</source>
        <translation>vŕtacia úloha potrebuje stroj s osami X a Y</translation>
    </message>
    <message>
        <source>teaching: read with an Excellon step of {0:g} inch (coordinates x {1:g})</source>
        <translation>výučba: čítané s krokom Excellon {0:g} palca (súradnice × {1:g})</translation>
    </message>
    <message>
        <source>a folder</source>
        <extracomment>How much of a file the format sniffers see.</extracomment>
        <translation>priečinok</translation>
    </message>
    <message>
        <source>a named pipe</source>
        <translation>pomenovaná rúra</translation>
    </message>
    <message>
        <source>a device</source>
        <translation>zariadenie</translation>
    </message>
    <message>
        <source>a block device</source>
        <translation>blokové zariadenie</translation>
    </message>
    <message>
        <source>a socket</source>
        <translation>soket</translation>
    </message>
    <message>
        <source>not a regular file</source>
        <translation>nie je bežný súbor</translation>
    </message>
    <message>
        <source>too large: {0}; job files are read up to {1}</source>
        <translation>príliš veľký: {0}; súbory úloh sa čítajú do {1}</translation>
    </message>
    <message>
        <source>too large: over {0}; job files are read up to that</source>
        <translation>príliš veľký: nad {0}; súbory úloh sa čítajú len do tejto veľkosti</translation>
    </message>
    <message>
        <source>cannot read: {0}</source>
        <translation>nedá sa čítať: {0}</translation>
    </message>
    <message>
        <source>cannot read: {0}, not a job file</source>
        <translation>nedá sa čítať: {0}, nie súbor úlohy</translation>
    </message>
    <message>
        <source>UTF-16 text (little-endian byte-order mark): save it as UTF-8 or ASCII</source>
        <translation>text v UTF-16 (značka poradia bajtov little-endian): uložte ho ako UTF-8 alebo ASCII</translation>
    </message>
    <message>
        <source>UTF-16 text (big-endian byte-order mark): save it as UTF-8 or ASCII</source>
        <translation>text v UTF-16 (značka poradia bajtov big-endian): uložte ho ako UTF-8 alebo ASCII</translation>
    </message>
    <message>
        <source>UTF-16 text (every other byte is zero): save it as UTF-8 or ASCII</source>
        <translation>text v UTF-16 (každý druhý bajt je nula): uložte ho ako UTF-8 alebo ASCII</translation>
    </message>
    <message>
        <source>binary data (a zero byte at offset {0}): not a job file</source>
        <translation>binárne dáta (nulový bajt na pozícii {0}): nejde o súbor úlohy</translation>
    </message>
    <message>
        <source>not UTF-8 text (byte 0x{0:02x})</source>
        <translation>nejde o text v UTF-8 (bajt 0x{0:02x})</translation>
    </message>
    <message>
        <source>move to {0}</source>
        <extracomment>G-code text a G-code machine is sent as written (G-code files); empty: the dialect renders the operation from its kind and target.</extracomment>
        <translation>nabehnúť na {0}</translation>
    </message>
    <message>
        <source>line {0}: {1} — {2}</source>
        <translation>riadok {0}: {1} — {2}</translation>
    </message>
    <message>
        <source>{0}: {1} — {2} {3:g} is outside {4:g}…{5:g}</source>
        <translation>{0}: {1} — {2} {3:g} je mimo rozsahu posuvu {4:g}…{5:g}</translation>
    </message>
    <message>
        <source>G92 without axis words (error:26): {0}</source>
        <translation>G92 bez súradníc osí (error:26): {0}</translation>
    </message>
    <message>
        <source>repeat {0} asks for {1} holes; a drill file may have at most {2}</source>
        <translation>opakovanie {0} žiada {1} otvorov; vŕtací súbor smie mať najviac {2}</translation>
    </message>
    <message>
        <source>more than {0} holes by this line; a drill file may have at most {0}</source>
        <translation>po tomto riadku viac ako {0} otvorov; vŕtací súbor smie mať najviac {0}</translation>
    </message>
    <message>
        <source>a coordinate is not a number: {0}</source>
        <translation>súradnica nie je číslo: {0}</translation>
    </message>
    <message>
        <source>{0} is not a G-code number (G-code has no exponent): it reads as {1} and {2}, and {3} has no {4} axis</source>
        <translation>{0} nie je číslo G-kódu (G-kód nepozná exponent): číta sa ako {1} a {2} a {3} nemá os {4}</translation>
    </message>
    <message>
        <source>{0}: {1} — {2} {3:g}: the machine has no {2} axis</source>
        <extracomment>What the loader wants the operator to know (e.g. the travel its ordering saved). Axes the job moves relative to wherever the machine stands when it starts (a G-code file&apos;s G91 or G92 before it set them); its positions on them are as if that were 0, so the runner starts it only from there. What :meth:`preview_path` gives: &quot;axes&quot;, the two axes asked for as they are (the preview projects them on a polar machine), or &quot;board&quot;, the work&apos;s own plane in mm whatever the axes (a job that knows its geometry projects itself, and better).</extracomment>
        <translation>{0}: {1} — {2} {3:g}: stroj nemá os {2}</translation>
    </message>
    <message>
        <source>change to pen T{0}</source>
        <extracomment>``M6``, ``M06 T2``, ``T2 M6``, ``m6t02``: the change, with its tool number before or after. The highest tool number GRBL takes (its T is a byte), as the parser refuses above it.</extracomment>
        <translation>vymeňte pero za T{0}</translation>
    </message>
    <message>
        <source>change the pen</source>
        <translation>vymeňte pero</translation>
    </message>
</context>
<context>
    <name>JobPreview</name>
    <message>
        <source>work</source>
        <extracomment>A click this many pixels from a hole picks it as a reference. Degrees per drawn step of a projected turn: an arc, not a chord, within a pixel or so. At most this many steps per move, so a move spinning the base many turns stays cheap. A path with more points than this is drawn without a dot on each. Points of the drawn reach circle. Runner states in which a job is under way: the machine is the job&apos;s, not the mouse&apos;s.</extracomment>
        <translation>práca</translation>
    </message>
    <message>
        <source>travel</source>
        <translation>prejazd</translation>
    </message>
    <message>
        <source>done</source>
        <translation>hotovo</translation>
    </message>
    <message>
        <source>machine</source>
        <translation>stroj</translation>
    </message>
    <message>
        <source>reach</source>
        <translation>dosah</translation>
    </message>
    <message>
        <source>travel limits</source>
        <translation>hranice posuvu</translation>
    </message>
    <message>
        <source>Move the machine?</source>
        <translation>Pohnúť strojom?</translation>
    </message>
    <message>
        <source>Drag pans, the wheel zooms, Fit shows it all; a click (not a drag) within the tool&apos;s reach turns the base and moves the tool there after you confirm</source>
        <translation>Ťahaním posuniete pohľad, kolieskom zväčšíte, Celé ukáže všetko; kliknutie (nie ťahanie) v dosahu nástroja po potvrdení natočí základňu a presunie tam nástroj</translation>
    </message>
    <message>
        <source>Drag pans, the wheel zooms, Fit shows it all; a click (not a drag) inside the travel limits moves the machine there after you confirm</source>
        <translation>Ťahaním posuniete pohľad, kolieskom zväčšíte, Celé ukáže všetko; kliknutie (nie ťahanie) vnútri hraníc posuvu po potvrdení presunie stroj na to miesto</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>Celé</translation>
    </message>
    <message>
        <source>Show the whole job (without a job, the tool&apos;s reach)</source>
        <translation>Zobraziť celú úlohu (bez úlohy dosah nástroja)</translation>
    </message>
    <message>
        <source>Show the whole job and the machine&apos;s travel</source>
        <translation>Zobraziť celú úlohu a rozsah posuvu stroja</translation>
    </message>
    <message>
        <source>x on the work</source>
        <extracomment>A string-art job&apos;s nails and thread (merged when huge), laid out here too. (x0, x1, y0, y1) of everything drawn, None when nothing is: fitting the view must not scan millions of points on the GUI thread. A merged thread&apos;s chords painted here (see :mod:`widgets.jobs.string_art_picture`). Points in the done trail&apos;s growing piece; past this it is frozen and a new piece starts. A refusal or news about click-to-move, for the dock&apos;s message area. A hole clicked while picking a reference: the reference (0-based) and the hole&apos;s index among the job&apos;s holes in drilling order (the registration row&apos;s numbering). The program now drawn (None: cleared), refused ones too: the drill page walks it. Wall seconds the last :meth:`set_program` took to build the curves. The reference the next click picks a hole for (None: a click moves the machine). Takes a click&apos;s plot point instead of a move (the &quot;Run from…&quot; dialog picks a stroke). Set on a cylindrical machine: the plot is the work&apos;s plane, not two axes.</extracomment>
        <translation>x na obrobku</translation>
    </message>
    <message>
        <source>y on the work</source>
        <translation>y na obrobku</translation>
    </message>
    <message>
        <source>a job is under way</source>
        <translation>prebieha úloha</translation>
    </message>
    <message>
        <source>motion is locked: {0}</source>
        <translation>pohyb je zablokovaný: {0}</translation>
    </message>
    <message>
        <source>not connected</source>
        <translation>nepripojené</translation>
    </message>
    <message>
        <source>Click-to-move refused ({0}): {1}</source>
        <translation>Presun kliknutím odmietnutý ({0}): {1}</translation>
    </message>
    <message>
        <source>{0} {1} is outside {2}…{3}</source>
        <translation>{0} {1} je mimo {2}…{3}</translation>
    </message>
    <message>
        <source>Click-to-move refused: {0} (soft limits)</source>
        <translation>Presun kliknutím odmietnutý: {0} (softvérové limity)</translation>
    </message>
    <message>
        <source>Move to {0} {1}?</source>
        <translation>Presunúť na {0} {1}?</translation>
    </message>
    <message>
        <source>Click-to-move cancelled</source>
        <translation>Presun kliknutím zrušený</translation>
    </message>
    <message>
        <source>The machine refused the move to {0}</source>
        <translation>Stroj odmietol presun na {0}</translation>
    </message>
    <message>
        <source>Moving to {0}</source>
        <translation>Presúvam na {0}</translation>
    </message>
    <message>
        <source>Click-to-move refused: {0} {1} from the centre is beyond {2}&apos;s travel 0…{3} (the reach)</source>
        <translation>Presun kliknutím odmietnutý: {0} {1} od stredu je mimo posuv osi {2} 0…{3} (dosah)</translation>
    </message>
    <message>
        <source>Turn {0} by {1}° to {2} {3}, then move {4} to {5} {6}?</source>
        <translation>Natočiť {0} o {1}° na {2} {3} a potom presunúť os {4} na {5} {6}?</translation>
    </message>
    <message>
        <source>Click a hole in the preview for reference {0}</source>
        <translation>Kliknite v náhľade na otvor pre referenčný bod {0}</translation>
    </message>
    <message>
        <source>No hole there: click on a hole, or press Pick again to stop</source>
        <translation>Tu nie je žiadny otvor: kliknite na otvor, alebo výber ukončite ďalším stlačením Vybrať</translation>
    </message>
    <message>
        <source>Hole {0} is reference {1}</source>
        <translation>Otvor {0} je referenčný bod {1}</translation>
    </message>
    <message>
        <source>Click-to-move is off: {0}</source>
        <translation>Presun kliknutím je vypnutý: {0}</translation>
    </message>
    <message>
        <source>Click a point within the tool&apos;s reach to move there (after confirming)</source>
        <translation>Kliknite na bod v dosahu nástroja a (po potvrdení) sa naň presuniete</translation>
    </message>
    <message>
        <source>Click a point inside the travel to move there (after confirming)</source>
        <translation>Kliknite na bod vnútri posuvu a (po potvrdení) sa naň presuniete</translation>
    </message>
    <message>
        <source>Preview: the {connections} connections are drawn merged, each of the {chords} different chords once, as dark as its windings make it</source>
        <extracomment>The thread&apos;s opacity (of 255): low, so that where threads cross the colour deepens. A merged thread&apos;s bands (see the module of the thread geometry), all and wound. The whole job&apos;s bands as one image painted on the loading thread, shown instead of ``thread_bands`` while the view is at the scale it was painted for. What the preview says when it draws the thread merged (&quot;&quot; when exact).</extracomment>
        <translation>Náhľad: {connections} spojení je vykreslených zlúčene, každá z {chords} rôznych tetív raz, tým tmavšia, čím viackrát je navinutá</translation>
    </message>
</context>
<context>
    <name>JobRunner</name>
    <message>
        <source>Stop the running job before loading another</source>
        <extracomment>Operations the machine reported as run, and the total. Equal to ``done`` where one operation is sent at a time; behind it on G-code, whose planner holds answered lines. Only the operator can tell whether an operation ran: question, &quot;again&quot; and &quot;done&quot; labels. Only the operator can say where an interrupted job goes on: a ResumeChoice. The station the job runs on (its profile, so its dialect, is kept for life). Operations done and executed, the estimate, the elapsed, running and waiting times and the time left; it emits the progress and ETA signals above. What the jog lock says while this runner&apos;s program is under way (a macro&apos;s runner says its own, so that neither kind of runner starts while the other&apos;s runs).</extracomment>
        <translation>Pred načítaním ďalšej úlohy zastavte tú bežiacu</translation>
    </message>
    <message>
        <source>Job {0} refused, {1} operation(s) cannot be run:
{2}</source>
        <translation>Úloha {0} odmietnutá, nedá sa vykonať operácií: {1}
{2}</translation>
    </message>
    <message>
        <source>Job {0} was interrupted: {1} of {2} operations done; resume from {3} or discard the checkpoint</source>
        <translation>Úloha {0} bola prerušená: hotovo {1} z {2} operácií; pokračujte od {3}, alebo kontrolný bod zahoďte</translation>
    </message>
    <message>
        <source>Resume from the checkpoint or discard it first</source>
        <translation>Najprv pokračujte od kontrolného bodu, alebo ho zahoďte</translation>
    </message>
    <message>
        <source>Job {0} not started from {1}: {2}</source>
        <translation>Úloha {0} nespustená od {1}: {2}</translation>
    </message>
    <message>
        <source>Answer the question about the interrupted operation first</source>
        <translation>Najprv odpovedzte na otázku k prerušenej operácii</translation>
    </message>
    <message>
        <source>Choose the line to resume from first</source>
        <translation>Najprv zvoľte riadok, od ktorého pokračovať</translation>
    </message>
    <message>
        <source>Job aborted after {0} of {1} operations</source>
        <translation>Úloha prerušená po {0} z {1} operácií</translation>
    </message>
    <message>
        <source>Checkpoint discarded; the job starts from the beginning</source>
        <translation>Kontrolný bod zahodený; úloha začne od začiatku</translation>
    </message>
    <message>
        <source>Job failed at {0}: {1}</source>
        <extracomment>The run stops after the operation under way (Step). A pause was asked for while an operation was under way (PAUSING). The operation the operator is asked about. Where to go on, for the operator to pick. Paused until the operator acts (an alarm, a board that restarted): nothing resumes it on its own (the scripting API ends the job instead). Paused because the link went, and nothing else has happened to the job since.</extracomment>
        <translation>Úloha zlyhala na {0}: {1}</translation>
    </message>
    <message>
        <source>Job paused at {0}: link {1}; resume once the machine is back</source>
        <translation>Úloha pozastavená na {0}: spojenie {1}; pokračujte, keď bude stroj späť</translation>
    </message>
    <message>
        <source>Job paused: link {0}; resume once the machine is back</source>
        <translation>Úloha pozastavená: spojenie {0}; pokračujte, keď bude stroj späť</translation>
    </message>
    <message>
        <source>Job {0} done: {1} operations in {2} s</source>
        <translation>Úloha {0} dokončená: operácií {1} za {2} s</translation>
    </message>
    <message>
        <source>, of which {0} s waiting for you</source>
        <translation>, z toho {0} s čakania na vás</translation>
    </message>
    <message>
        <source>Job {0} not started: it moves {1} relative to where the machine stands (G91 or G92 before any absolute move), and was checked from 0; the machine is at {2}. Home it or move it to 0 first.</source>
        <translation>Úloha {0} nespustená: pohybuje {1} relatívne k miestu, kde stroj stojí (G91 alebo G92 pred prvým absolútnym pohybom), a bola skontrolovaná od 0; stroj je na {2}. Najprv vykonajte referenčnú jazdu alebo ho presuňte na 0.</translation>
    </message>
    <message>
        <source>not connected</source>
        <translation>nepripojené</translation>
    </message>
    <message>
        <source>Cannot run the job: {0}</source>
        <translation>Úlohu nemožno spustiť: {0}</translation>
    </message>
    <message>
        <source>a job is under way — abort it or let it finish</source>
        <extracomment>Refused operations listed in the message (the dock&apos;s list holds them all). How far from 0 (mm or degrees) a job that counts from its start may start.</extracomment>
        <translation>prebieha úloha — prerušte ju, alebo ju nechajte dobehnúť</translation>
    </message>
    <message>
        <source>The machine answers again, but {0}: the job stays paused. Check the machine, then Resume</source>
        <translation>Stroj opäť odpovedá, ale {0}: úloha zostáva pozastavená. Skontrolujte stroj a potom dajte Pokračovať</translation>
    </message>
    <message>
        <source>The machine answers again, its state intact: the job goes on</source>
        <translation>Stroj opäť odpovedá a jeho stav je neporušený: úloha pokračuje</translation>
    </message>
    <message>
        <source>{0} is not supported on {1}</source>
        <translation>{0}: stroj {1} to nepodporuje</translation>
    </message>
    <message>
        <source>{0} cannot drill</source>
        <translation>{0} nevie vŕtať</translation>
    </message>
    <message>
        <source>{0} drills only with explicit moves: G-code has no drill cycle</source>
        <translation>{0} vŕta len výslovnými pohybmi: G-code nemá vŕtací cyklus</translation>
    </message>
    <message>
        <source>{0} has no pen</source>
        <translation>{0} nemá pero</translation>
    </message>
    <message>
        <source>{0} does not take G-code</source>
        <translation>{0} neprijíma G-kód</translation>
    </message>
    <message>
        <source>{0}: a drill cycle drills where the tool stands; start at op {1}, the move to its hole</source>
        <extracomment>Link states in which nothing can be sent. Whether G-code lines (``OpKind.GCODE``) can be sent as they are.</extracomment>
        <translation>{0}: vŕtací cyklus vŕta tam, kde nástroj stojí; začnite od op. {1}, nájazdu na jeho otvor</translation>
    </message>
    <message>
        <source>the drill is busy with another command</source>
        <translation>vŕtačka je zaneprázdnená iným príkazom</translation>
    </message>
    <message>
        <source>the drill refused it</source>
        <translation>vŕtačka ho odmietla</translation>
    </message>
    <message>
        <source>the drill refused to home</source>
        <translation>vŕtačka odmietla referenčnú jazdu</translation>
    </message>
    <message>
        <source>The drill cannot report whether it has homed, and the station has not seen it home since this link opened: homing first (N)</source>
        <translation>Vŕtačka nevie ohlásiť, či prešla referenčnou jazdou, a stanica ju od otvorenia spojenia referenčnú jazdu robiť nevidela: najprv referenčná jazda (N)</translation>
    </message>
    <message>
        <source>Parking at {0}</source>
        <translation>Parkovanie na {0}</translation>
    </message>
    <message>
        <source>Drill cycle at {0} was received by the machine, which finishes it on its own: counted as done</source>
        <translation>Vŕtací cyklus na {0} stroj prijal a dokončí ho sám: počíta sa ako hotový</translation>
    </message>
    <message>
        <source>the drill refused {0}</source>
        <translation>vŕtačka odmietla {0}</translation>
    </message>
    <message>
        <source>Not parked: the drill refused {0}</source>
        <translation>Nezaparkované: vŕtačka odmietla {0}</translation>
    </message>
    <message>
        <source>the move was refused</source>
        <extracomment>Position echoes per moved axis, counted from a resume, before the machine&apos;s state is believed: more than a killed station can leave unread in a serial buffer.
----------
Station-clock seconds the unit has to show it started a move, or to say where it stands. Per axis of the operation: mm and station-clock time of its last report since the move (or the question) went out. Station-clock time the unit was asked where it stands because it fell silent short of the end: its answer, not the silence, says whether it stopped short. The last position each axis reported. A report is judged as it is decoded, before the session folds it into the model, so the model lags by the report under judgement.</extracomment>
        <translation>pohyb bol odmietnutý</translation>
    </message>
    <message>
        <source>Checking whether {0} ({1}) was completed…</source>
        <translation>Overuje sa, či bola operácia {0} ({1}) dokončená…</translation>
    </message>
    <message>
        <source>Operation at {0} was already complete</source>
        <translation>Operácia na {0} už bola dokončená</translation>
    </message>
    <message>
        <source>{0} hit an end switch at {1} mm</source>
        <translation>{0} narazila na koncový spínač na {1} mm</translation>
    </message>
    <message>
        <source>Asking the unit where it stands ({0}, {1})…</source>
        <translation>Dopyt na polohu jednotky ({0}, {1})…</translation>
    </message>
    <message>
        <source>Starting at {0}: the machine goes there with the pen up, set as the file had it ({1})</source>
        <extracomment>Lines that may change the modal state this module follows (a literal-ish search over the text before the start; each hit is then read word by word). Motion words, and the codes they are. Words that make the position at the start unknown to the station&apos;s model. File offsets smaller than this (mm) are none. Operations after the start looked at for the move that needs the arc&apos;s word. Where the machine stands (program coordinates, mm), and whether the pen is down. The motion mode in force (``G0``…``G3``), None when the file set none yet. The feed in force, in the file&apos;s units per minute at the start (None: never set). The file&apos;s own G92 offset per axis (mm), as :func:`file_offset` gives it. The last operator prompt before the start (a pen or bit change), if any. The operation that gets the arc&apos;s motion word in front (see the module doc). The program is a G-code file whose own modal state is rebuilt (else only the position and the pen, as a resume does: its lines carry their own words).</extracomment>
        <translation>Začína sa od {0}: stroj tam nabehne so zdvihnutým perom, nastavený tak, ako ho tam mal súbor ({1})</translation>
    </message>
    <message>
        <source>; the file&apos;s last prompt before it was: {0}</source>
        <translation>; posledná výzva súboru pred týmto miestom bola: {0}</translation>
    </message>
    <message>
        <source>this job does not run in the order of its file&apos;s lines: start from an operation number instead</source>
        <translation>táto úloha nebeží v poradí riadkov svojho súboru: začnite radšej od čísla operácie</translation>
    </message>
    <message>
        <source>lines count from 1</source>
        <translation>riadky sa číslujú od 1</translation>
    </message>
    <message>
        <source>beyond the end: nothing runs after line {0}</source>
        <translation>za koncom: po riadku {0} sa už nič nevykonáva</translation>
    </message>
    <message>
        <source>the job has operations 1 to {0}</source>
        <translation>úloha má operácie 1 až {0}</translation>
    </message>
    <message>
        <source>{0} before the start changes where the file&apos;s coordinates are, which the station does not follow: start before this line</source>
        <translation>{0} pred začiatkom mení, kde sú súradnice súboru, a to stanica nesleduje: začnite pred týmto riadkom</translation>
    </message>
</context>
<context>
    <name>JobsDock</name>
    <message>
        <source>Which kind of job?</source>
        <extracomment>A refused file&apos;s further refused lines listed under the first one. Asks which job type an ambiguous file is; the chosen type&apos;s key, None when cancelled.</extracomment>
        <translation>Aký druh úlohy?</translation>
    </message>
    <message>
        <source>{0}: the name and the content do not tell.
Read it as:</source>
        <translation>{0}: z názvu ani obsahu sa to nedá určiť.
Načítať ako:</translation>
    </message>
    <message>
        <source>Jobs</source>
        <extracomment>A job file was loaded (its path): the window lists it under File → Recent jobs.
----------
Docks of features built elsewhere (the macros&apos;), by object name → their builder: shown again at start and saved with these (:meth:`place_dock` places them).</extracomment>
        <translation>Úlohy</translation>
    </message>
    <message>
        <source>The operation being executed and the line it came from</source>
        <translation>Práve vykonávaná operácia a riadok, z ktorého pochádza</translation>
    </message>
    <message>
        <source>Messages about the job appear here</source>
        <translation>Tu sa objavia správy o úlohe</translation>
    </message>
    <message>
        <source>Draw holes with the pen</source>
        <extracomment>An option changed (or the drill&apos;s timing, which the estimate reads): read the file again.</extracomment>
        <translation>Otvory kresliť perom</translation>
    </message>
    <message>
        <source>Drill files: instead of drilling, the pen goes down (K) at each bit&apos;s first hole, draws along the following holes, X then Y, and comes up (Z) after the last, as the original tool drew</source>
        <translation>Vŕtacie súbory: namiesto vŕtania zíde pero (K) na prvý otvor každého vrtáka, kreslí pozdĺž ďalších otvorov, najprv X, potom Y, a za posledným sa zdvihne (Z), ako kreslil pôvodný program</translation>
    </message>
    <message>
        <source>Crosses at the holes</source>
        <translation>Krížiky na otvoroch</translation>
    </message>
    <message>
        <source>Drawn drill files: a pen cross the size of each hole instead of one line along the holes</source>
        <translation>Kreslené vŕtacie súbory: perom krížik veľkosti každého otvoru namiesto jednej čiary pozdĺž otvorov</translation>
    </message>
    <message>
        <source>Smallest bit first</source>
        <translation>Najmenší vrták prvý</translation>
    </message>
    <message>
        <source>Drill files: the bit changes ordered from the smallest drill to the largest</source>
        <translation>Vŕtacie súbory: výmeny vrtákov od najmenšieho po najväčší</translation>
    </message>
    <message>
        <source>1/{0} inch</source>
        <translation>1/{0} palca</translation>
    </message>
    <message>
        <source>Excellon step: the unit of bare integer coordinates</source>
        <translation>Krok Excellon: jednotka celočíselných súradníc bez formátu</translation>
    </message>
    <message>
        <source>Excellon step</source>
        <translation>Krok Excellon</translation>
    </message>
    <message>
        <source>Use this machine&apos;s pen commands</source>
        <translation>Použiť príkazy pera tohto stroja</translation>
    </message>
    <message>
        <source>G-code: M300/M280 servo lines, Z pen heights, M3/M5 are sent as this machine&apos;s own pen-up / pen-down commands</source>
        <translation>G-kód: riadky serva M300/M280, výšky pera v Z a M3/M5 sa posielajú ako vlastné príkazy tohto stroja na zdvihnutie / spustenie pera</translation>
    </message>
    <message>
        <source>Skip lines it cannot run</source>
        <translation>Preskočiť nevykonateľné riadky</translation>
    </message>
    <message>
        <source>G-code: lines this machine cannot execute (e.g. M18) are listed and left out instead of refusing the job</source>
        <translation>G-kód: riadky, ktoré tento stroj nevie vykonať (napr. M18), sa vypíšu a vynechajú, namiesto aby bola úloha odmietnutá</translation>
    </message>
    <message>
        <source>Open…</source>
        <translation>Otvoriť…</translation>
    </message>
    <message>
        <source>Open a job file (point list; the type is told by its content)</source>
        <translation>Otvoriť súbor úlohy (zoznam bodov; typ sa rozpozná podľa obsahu)</translation>
    </message>
    <message>
        <source>Export…</source>
        <translation>Exportovať…</translation>
    </message>
    <message>
        <source>Write the loaded job out: G-code, or a string-art job&apos;s SD-card files</source>
        <translation>Zapísať načítanú úlohu: G-kód alebo súbory pre SD kartu pri string arte</translation>
    </message>
    <message>
        <source>From photo…</source>
        <extracomment>The &quot;From photo…&quot; dialog while it is open.</extracomment>
        <translation>Z fotografie…</translation>
    </message>
    <message>
        <source>String art from a photo: make a nail sequence, see it, load it as a job</source>
        <translation>String art z fotografie: vytvoriť poradie klincov, pozrieť si ho a načítať ako úlohu</translation>
    </message>
    <message>
        <source>no job loaded</source>
        <translation>žiadna úloha nenačítaná</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Spustiť</translation>
    </message>
    <message>
        <source>Run the job from the start</source>
        <translation>Spustiť úlohu od začiatku</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pozastaviť</translation>
    </message>
    <message>
        <source>Pause after the operation under way finishes</source>
        <translation>Pozastaviť po dokončení prebiehajúcej operácie</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Pokračovať</translation>
    </message>
    <message>
        <source>Go on from where the job paused</source>
        <translation>Pokračovať tam, kde sa úloha pozastavila</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Krok</translation>
    </message>
    <message>
        <source>Execute the next operation only, then pause</source>
        <translation>Vykonať len ďalšiu operáciu a pozastaviť</translation>
    </message>
    <message>
        <source>Abort</source>
        <translation>Prerušiť</translation>
    </message>
    <message>
        <source>Stop the machine now and end the job</source>
        <translation>Okamžite zastaviť stroj a ukončiť úlohu</translation>
    </message>
    <message>
        <source>Time since the job started, prompts and pauses included; of it, how long the machine waited for you</source>
        <translation>Čas od spustenia úlohy vrátane výziev a prestávok; z toho, ako dlho stroj čakal na vás</translation>
    </message>
    <message>
        <source>Go on after the last operation the machine completed; none is repeated</source>
        <translation>Pokračovať za poslednou operáciou, ktorú stroj dokončil; nič sa neopakuje</translation>
    </message>
    <message>
        <source>Discard</source>
        <translation>Zahodiť</translation>
    </message>
    <message>
        <source>Forget the interrupted run; Run then starts from the first operation</source>
        <translation>Zabudnúť prerušený beh; Spustiť potom začne prvou operáciou</translation>
    </message>
    <message>
        <source>Continue</source>
        <translation>Pokračovať</translation>
    </message>
    <message>
        <source>Done: let the job go on</source>
        <translation>Hotovo: úloha môže pokračovať</translation>
    </message>
    <message>
        <source>Again</source>
        <translation>Znova</translation>
    </message>
    <message>
        <source>It did not happen: send it again</source>
        <translation>Neprebehlo: odoslať znova</translation>
    </message>
    <message>
        <source>Done</source>
        <translation>Hotovo</translation>
    </message>
    <message>
        <source>It happened: count it as done</source>
        <translation>Prebehlo: započítať ako hotové</translation>
    </message>
    <message>
        <source>Time left, from the dry run of the job on the machine&apos;s model</source>
        <translation>Zostávajúci čas podľa skúšobného prechodu úlohy na modeli stroja</translation>
    </message>
    <message>
        <source>Open a job</source>
        <translation>Otvoriť úlohu</translation>
    </message>
    <message>
        <source>{0}: not opened — a job is under way (abort it first)</source>
        <translation>{0}: neotvorené — prebieha úloha (najprv ju prerušte)</translation>
    </message>
    <message>
        <source>{0}: not opened — still reading {1}</source>
        <translation>{0}: neotvorené — ešte sa načítava {1}</translation>
    </message>
    <message>
        <source>reading {0}…</source>
        <translation>načítavam {0}…</translation>
    </message>
    <message>
        <source>{0}: not loaded — {1}</source>
        <translation>{0}: nenačítané — {1}</translation>
    </message>
    <message>
        <source>{0} — not loaded</source>
        <translation>{0} — nenačítané</translation>
    </message>
    <message numerus="yes">
        <source>… and %n more line(s) refused</source>
        <translation>
            <numerusform>… a odmietnutý ešte %n ďalší riadok</numerusform>
            <numerusform>… a odmietnuté ešte %n ďalšie riadky</numerusform>
            <numerusform>… a odmietnutých ešte %n ďalších riadkov</numerusform>
        </translation>
    </message>
    <message>
        <source>{0}: the board placement was not applied: {1}</source>
        <translation>{0}: umiestnenie dosky nebolo použité: {1}</translation>
    </message>
    <message>
        <source>{0}: kept on the board as before ({1})</source>
        <translation>{0}: ponechané na doske ako predtým ({1})</translation>
    </message>
    <message>
        <source>{0} — refused, preview only</source>
        <translation>{0} — odmietnuté, len náhľad</translation>
    </message>
    <message numerus="yes">
        <source>{0}: %n operation(s) loaded</source>
        <translation>
            <numerusform>{0}: načítaná %n operácia</numerusform>
            <numerusform>{0}: načítané %n operácie</numerusform>
            <numerusform>{0}: načítaných %n operácií</numerusform>
        </translation>
    </message>
    <message>
        <source>loaded</source>
        <translation>načítané</translation>
    </message>
    <message>
        <source>SD-card files (param.txt, poradi.txt)…</source>
        <translation>Súbory pre SD kartu (param.txt, poradi.txt)…</translation>
    </message>
    <message>
        <source>G-code program…</source>
        <translation>Program v G-kóde…</translation>
    </message>
    <message>
        <source>Nothing to export for this job on this machine</source>
        <translation>Pri tejto úlohe na tomto stroji nie je čo exportovať</translation>
    </message>
    <message>
        <source>Folder for param.txt and poradi.txt</source>
        <translation>Priečinok pre param.txt a poradi.txt</translation>
    </message>
    <message>
        <source>Export G-code</source>
        <translation>Exportovať G-kód</translation>
    </message>
    <message>
        <source>G-code (*.gcode)</source>
        <translation>G-kód (*.gcode)</translation>
    </message>
    <message>
        <source>Only string-art jobs have SD-card files</source>
        <translation>Súbory pre SD kartu majú len úlohy string art</translation>
    </message>
    <message>
        <source>SD-card files not written: {0}</source>
        <translation>Súbory pre SD kartu nezapísané: {0}</translation>
    </message>
    <message>
        <source>Wrote {0} and {1}</source>
        <translation>Zapísané {0} a {1}</translation>
    </message>
    <message>
        <source>G-code not written: {0}</source>
        <translation>G-kód nezapísaný: {0}</translation>
    </message>
    <message>
        <source>Wrote {0}</source>
        <translation>Zapísané {0}</translation>
    </message>
    <message numerus="yes">
        <source>{0} — %n operation(s)</source>
        <translation>
            <numerusform>{0} — %n operácia</numerusform>
            <numerusform>{0} — %n operácie</numerusform>
            <numerusform>{0} — %n operácií</numerusform>
        </translation>
    </message>
    <message>
        <source>the end</source>
        <translation>koniec</translation>
    </message>
    <message numerus="yes">
        <source>An interrupted run of &lt;b&gt;{0}&lt;/b&gt; completed {1} of %n operation(s). Resume from operation {2} ({3})?</source>
        <translation>
            <numerusform>Prerušený beh &lt;b&gt;{0}&lt;/b&gt; dokončil {1} z %n operácie. Pokračovať od operácie {2} ({3})?</numerusform>
            <numerusform>Prerušený beh &lt;b&gt;{0}&lt;/b&gt; dokončil {1} z %n operácií. Pokračovať od operácie {2} ({3})?</numerusform>
            <numerusform>Prerušený beh &lt;b&gt;{0}&lt;/b&gt; dokončil {1} z %n operácií. Pokračovať od operácie {2} ({3})?</numerusform>
        </translation>
    </message>
    <message>
        <source>Resume from op {0}</source>
        <translation>Pokračovať od op. {0}</translation>
    </message>
    <message>
        <source> — motion locked: {0}</source>
        <translation> — pohyb zablokovaný: {0}</translation>
    </message>
    <message numerus="yes">
        <source>{0} / %n ops</source>
        <extracomment>The file ``_source_lines`` came from and the program they were read for. The board the operator gave for a bare nail list (kept while the file is re-read). The job type the operator chose for an ambiguous file (kept while it is re-read). An option changed while a file was being read: read it again when that ends. The source lines the loading thread read with the program (None: read them here).</extracomment>
        <translation>
            <numerusform>{0} / %n op.</numerusform>
            <numerusform>{0} / %n op.</numerusform>
            <numerusform>{0} / %n op.</numerusform>
        </translation>
    </message>
    <message>
        <source>{0} sent</source>
        <translation>odoslaných {0}</translation>
    </message>
    <message>
        <source>Operations the machine reported as run, of all; and how many were sent to it (a G-code machine holds sent lines in its planner before it runs them)</source>
        <translation>Operácie, ktoré stroj ohlásil ako vykonané, zo všetkých; a koľko mu ich bolo odoslaných (stroj s G-kódom drží odoslané riadky v plánovači, kým ich vykoná)</translation>
    </message>
    <message>
        <source>elapsed {0}</source>
        <translation>uplynulo {0}</translation>
    </message>
    <message>
        <source>(of which {0} waiting for you)</source>
        <translation>(z toho {0} čakania na vás)</translation>
    </message>
    <message>
        <source>left {0}</source>
        <translation>zostáva {0}</translation>
    </message>
    <message>
        <source>file: {0}</source>
        <translation>súbor: {0}</translation>
    </message>
    <message>
        <source>machine: {0} microsteps</source>
        <translation>stroj: {0} mikrokrokov</translation>
    </message>
    <message>
        <source>Operator: {0}</source>
        <translation>Obsluha: {0}</translation>
    </message>
    <message>
        <source>waiting for the operator: {0}</source>
        <translation>čaká sa na obsluhu: {0}</translation>
    </message>
    <message>
        <source>op {0}: {1}  {2}</source>
        <translation>op. {0}: {1}  {2}</translation>
    </message>
    <message>
        <source>Run from a line</source>
        <translation>Spustiť od riadku</translation>
    </message>
    <message>
        <source>Pick the line to start from, here or by clicking its stroke in the preview. The machine goes there with the pen up, set as the file had it there (units, distance mode, feed, offsets, pen), then carries on; the lines before it count as run.</source>
        <translation>Vyberte riadok, od ktorého začať, tu alebo kliknutím na jeho ťah v náhľade. Stroj tam nabehne so zdvihnutým perom, nastavený tak, ako ho tam mal súbor (jednotky, režim vzdialeností, posuv, posunutia, pero), a pokračuje; riadky pred ním sa počítajú ako vykonané.</translation>
    </message>
    <message>
        <source>Run from here</source>
        <translation>Spustiť odtiaľto</translation>
    </message>
    <message>
        <source>On this machine pick the line in the list</source>
        <translation>Na tomto stroji vyberte riadok v zozname</translation>
    </message>
    <message>
        <source>Working out the machine&apos;s state at {0}…</source>
        <translation>Zisťujem stav stroja na {0}…</translation>
    </message>
    <message>
        <source>Run from…</source>
        <translation>Spustiť od…</translation>
    </message>
    <message>
        <source>Start the job at a line you pick (list or preview) ({0})</source>
        <translation>Spustiť úlohu od riadku, ktorý vyberiete (zoznam alebo náhľad) ({0})</translation>
    </message>
</context>
<context>
    <name>JogInput</name>
    <message>
        <source>Jog refused: {0}</source>
        <extracomment>The jog vector (one -1/0/+1 per axis) after every change. The jog the held arrow keys alone ask for (one -1/0/+1 per axis), after every change: the on-screen button for that direction shows itself pressed. Stop (Esc, a Stop button) was asked, before the session is told: a job under way must end with it, or it would set the machine going again on its own. Whether this machine jogs at all: if not, no key is a jog key. Why input is refused while disabled (said when a key or button is pressed anyway). What a tap of an arrow key moves; 0: the key jogs while held (see ``set_key_step``).</extracomment>
        <translation>Ručný posuv odmietnutý: {0}</translation>
    </message>
</context>
<context>
    <name>JoystickBox</name>
    <message>
        <source>Joystick (usb3 unit)</source>
        <translation>Joystick (jednotka usb3)</translation>
    </message>
    <message>
        <source>{0} stick: 500…524 is the dead zone; let go to centre it</source>
        <extracomment>The unit&apos;s end switches (FIDELITY S4-18), closed where the axis is now.</extracomment>
        <translation>Páčka {0}: 500…524 je mŕtve pásmo; po pustení sa vráti na stred</translation>
    </message>
</context>
<context>
    <name>LinkDetail</name>
    <message>
        <source>built-in emulator</source>
        <extracomment>Link details the transports give in English (protocol/ has no Qt to translate them).</extracomment>
        <translation>vstavaný emulátor</translation>
    </message>
</context>
<context>
    <name>LinkState</name>
    <message>
        <source>disconnected</source>
        <translation>odpojené</translation>
    </message>
    <message>
        <source>connecting</source>
        <translation>pripájam</translation>
    </message>
    <message>
        <source>connected</source>
        <translation>pripojené</translation>
    </message>
    <message>
        <source>stale</source>
        <translation>bez čerstvých dát</translation>
    </message>
    <message>
        <source>lost</source>
        <translation>stratené</translation>
    </message>
</context>
<context>
    <name>MachineModel</name>
    <message>
        <source>not connected</source>
        <extracomment>The machine position: travel limits and every motion check use it. The work coordinate offset (GRBL&apos;s WCO: machine minus work position); 0 elsewhere. Why the operator may not jog now though the machine may move (a job under way).</extracomment>
        <translation>nepripojené</translation>
    </message>
    <message>
        <source>link lost</source>
        <translation>spojenie stratené</translation>
    </message>
    <message>
        <source>sleeping — press Wake</source>
        <translation>spí — stlačte Zobudiť</translation>
    </message>
</context>
<context>
    <name>MachineProfile</name>
    <message>
        <source>XY positioning stage</source>
        <extracomment>How far a reported position may stray from the path of the moves sent ([supervision] tolerance_mm): a few steps, a rounded report and a report read while the move went on. What a GRBL-compatible board executes (docs/protocols.md §4 plus the usual GRBL extras). &quot;counting&quot; (at most rx_buffer - 1 bytes unacknowledged) or &quot;ping-pong&quot; G1/G2/G3 need a feed rate set first (GRBL&apos;s error:22); False: the firmware has a default. The unit of ``G4 P``: &quot;s&quot; on GRBL (P150 is two and a half minutes), &quot;ms&quot; on firmwares that read it as Marlin does. The loader, the estimate and the emulator follow it. GRBL&apos;s ``$11`` (mm): the board joins moves at their junction speed, planning ``planner_blocks`` ahead, and the estimate plans as it does; None (firmwares without a look-ahead planner): every move starts and ends at rest. A bare ``G92`` makes the current position the origin (the CoreXY plotter&apos;s firmware); False: GRBL&apos;s, which refuses it (error:26) and needs the axes named. The board answers a line only once its motion is done (the CoreXY plotter), not once planned (GRBL): every answered line ran, and an unanswered one is at most the one under way — what a resume after a fault can take as proven. A firmware that ignores F and runs G0 as G1, stepping its lead motor at one interval that only ``M98 &lt;µs&gt;`` changes (the CoreXY plotter, FIDELITY S1-01): its power-on interval in µs. None: F sets the speed (GRBL, the winder). A GRBL board&apos;s job lines go compact (:attr:`compact_lines`); False: as written.</extracomment>
        <translation>Polohovací stôl XY</translation>
    </message>
    <message>
        <source>Three-axis USB unit</source>
        <translation>Trojosová jednotka USB</translation>
    </message>
    <message>
        <source>PCB drill/plotter</source>
        <translation>Vŕtačka/plotter plošných spojov</translation>
    </message>
    <message>
        <source>String-art winder</source>
        <translation>Navíjačka string-artu</translation>
    </message>
    <message>
        <source>CoreXY pen plotter</source>
        <translation>Perový plotter CoreXY</translation>
    </message>
    <message>
        <source>GRBL pen plotter</source>
        <translation>Perový plotter GRBL</translation>
    </message>
</context>
<context>
    <name>MacroEditor</name>
    <message>
        <source>Macros — {0}</source>
        <translation>Makrá — {0}</translation>
    </message>
    <message>
        <source>&amp;Name</source>
        <translation>&amp;Názov</translation>
    </message>
    <message>
        <source>&amp;G-code</source>
        <translation>&amp;G-kód</translation>
    </message>
    <message>
        <source>&amp;Add</source>
        <translation>&amp;Pridať</translation>
    </message>
    <message>
        <source>&amp;Delete</source>
        <translation>&amp;Vymazať</translation>
    </message>
    <message>
        <source>&amp;Up</source>
        <translation>Na&amp;hor</translation>
    </message>
    <message>
        <source>Do&amp;wn</source>
        <translation>Na&amp;dol</translation>
    </message>
    <message>
        <source>&amp;Import…</source>
        <translation>&amp;Importovať…</translation>
    </message>
    <message>
        <source>&amp;Export…</source>
        <translation>&amp;Exportovať…</translation>
    </message>
    <message>
        <source>(no name)</source>
        <translation>(bez názvu)</translation>
    </message>
    <message>
        <source>Macro {0}</source>
        <translation>Makro {0}</translation>
    </message>
    <message>
        <source>Import macros</source>
        <translation>Importovať makrá</translation>
    </message>
    <message>
        <source>Macro files (*.toml)</source>
        <translation>Súbory makier (*.toml)</translation>
    </message>
    <message>
        <source>{0} macro(s) imported</source>
        <translation>Importovaných makier: {0}</translation>
    </message>
    <message>
        <source>Export macros</source>
        <translation>Exportovať makrá</translation>
    </message>
    <message>
        <source>Exported to {0}</source>
        <translation>Exportované do {0}</translation>
    </message>
</context>
<context>
    <name>Macros</name>
    <message>
        <source>no G-code to send in the macro</source>
        <translation>makro neobsahuje žiadny G-kód na odoslanie</translation>
    </message>
    <message>
        <source>{0}: {1} {2:g} is outside the travel {3:g}…{4:g}</source>
        <translation>{0}: {1} {2:g} je mimo rozsahu posuvu {3:g}…{4:g}</translation>
    </message>
    <message>
        <source>a macro is under way — stop it or let it finish</source>
        <extracomment>Refusals listed in a message; more are counted.</extracomment>
        <translation>beží makro — zastavte ho, alebo ho nechajte dobehnúť</translation>
    </message>
    <message>
        <source>… and {0} more</source>
        <translation>… a ďalších {0}</translation>
    </message>
    <message>
        <source>{0} takes no G-code macros</source>
        <extracomment>The macro run&apos;s JobState. A macro&apos;s ``M0``/``M6`` asks the operator (confirm with :meth:`confirm`). The macro running, or last run. While a macro is loaded: the runner&apos;s words about an earlier run&apos;s checkpoint (a macro always starts from its start) are not the operator&apos;s business.</extracomment>
        <translation>{0} neprijíma makrá v G-kóde</translation>
    </message>
    <message>
        <source>macro {0} is running</source>
        <translation>beží makro {0}</translation>
    </message>
    <message>
        <source>not connected</source>
        <translation>nepripojené</translation>
    </message>
    <message>
        <source>the machine is moving</source>
        <translation>stroj sa pohybuje</translation>
    </message>
    <message>
        <source>the travel check failed</source>
        <translation>kontrola posuvu zlyhala</translation>
    </message>
    <message>
        <source>it did not start</source>
        <translation>nespustilo sa</translation>
    </message>
    <message>
        <source>Macro {0} refused: {1}</source>
        <translation>Makro {0} odmietnuté: {1}</translation>
    </message>
    <message>
        <source>Macro {0} ended: the machine needs you first</source>
        <translation>Makro {0} ukončené: stroj najprv potrebuje vás</translation>
    </message>
    <message>
        <source>a macro needs a name</source>
        <extracomment>A bar of buttons, not a program library: more than this is a job file. A snippet, not a job: a few lines a person reads before pressing its button.</extracomment>
        <translation>makro potrebuje názov</translation>
    </message>
    <message>
        <source>the name starts or ends with a space</source>
        <translation>názov začína alebo končí medzerou</translation>
    </message>
    <message>
        <source>the name is longer than {0} characters</source>
        <translation>názov je dlhší ako {0} znakov</translation>
    </message>
    <message>
        <source>the name may hold printable characters only, and no quote</source>
        <translation>názov smie obsahovať iba tlačiteľné znaky a žiadne úvodzovky</translation>
    </message>
    <message>
        <source>the G-code is not text</source>
        <translation>G-kód nie je text</translation>
    </message>
    <message>
        <source>the G-code is longer than {0} characters</source>
        <translation>G-kód je dlhší ako {0} znakov</translation>
    </message>
    <message>
        <source>the G-code has more than {0} lines</source>
        <translation>G-kód má viac ako {0} riadkov</translation>
    </message>
    <message>
        <source>line {0} holds a character that is not printable text</source>
        <translation>riadok {0} obsahuje netlačiteľný znak</translation>
    </message>
    <message>
        <source>more than {0} macros</source>
        <translation>viac ako {0} makier</translation>
    </message>
    <message>
        <source>two macros are named {0}</source>
        <translation>dve makrá sa volajú {0}</translation>
    </message>
    <message>
        <source>{0}: not TOML ({1})</source>
        <extracomment>32 macros of 8000 characters, escaped, is well under this; more is not a macro file.</extracomment>
        <translation>{0}: nie je TOML ({1})</translation>
    </message>
    <message>
        <source>{0}: not a StepDeck macro file (format {1})</source>
        <translation>{0}: nie je súbor makier StepDecku (formát {1})</translation>
    </message>
    <message>
        <source>{0}: [[macro]] must be a list of at most {1} tables</source>
        <translation>{0}: [[macro]] musí byť zoznam najviac {1} tabuliek</translation>
    </message>
    <message>
        <source>{0}: macro {1} is not a table</source>
        <translation>{0}: makro {1} nie je tabuľka</translation>
    </message>
    <message>
        <source>{0}: macro {1}: {2}</source>
        <translation>{0}: makro {1}: {2}</translation>
    </message>
    <message>
        <source>{0}: not a file</source>
        <translation>{0}: nie je súbor</translation>
    </message>
    <message>
        <source>{0}: too large for a macro file</source>
        <translation>{0}: na súbor makier príliš veľký</translation>
    </message>
    <message>
        <source>{0}: not readable ({1})</source>
        <translation>{0}: nedá sa prečítať ({1})</translation>
    </message>
</context>
<context>
    <name>MacrosDock</name>
    <message>
        <source>Macros</source>
        <extracomment>The dock&apos;s object name: where the window&apos;s saved layout places it. Ctrl+1 … Ctrl+9.
----------
Buttons a row.</extracomment>
        <translation>Makrá</translation>
    </message>
    <message>
        <source>No macros yet: Edit… adds one.</source>
        <translation>Zatiaľ žiadne makrá: pridáte ich v Upraviť…</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stop</translation>
    </message>
    <message>
        <source>Stop the macro (Esc)</source>
        <translation>Zastaviť makro (Esc)</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Pokračovať</translation>
    </message>
    <message>
        <source>Go on after a pause or a prompt</source>
        <translation>Pokračovať po pauze alebo výzve</translation>
    </message>
    <message>
        <source>Edit…</source>
        <translation>Upraviť…</translation>
    </message>
    <message>
        <source>Add, change, order, import and export</source>
        <translation>Pridať, zmeniť, zoradiť, importovať a exportovať</translation>
    </message>
    <message>
        <source>No macro {0}</source>
        <translation>Makro {0} neexistuje</translation>
    </message>
    <message>
        <source>Macro {0} waits: {1} — Resume when done</source>
        <translation>Makro {0} čaká: {1} — keď budete hotoví, stlačte Pokračovať</translation>
    </message>
    <message>
        <source>Macros locked: {0}</source>
        <translation>Makrá zamknuté: {0}</translation>
    </message>
    <message>
        <source>{0}: %v of %m</source>
        <translation>{0}: %v z %m</translation>
    </message>
    <message>
        <source>{0}: done</source>
        <translation>{0}: hotovo</translation>
    </message>
    <message>
        <source>{0}: stopped</source>
        <translation>{0}: zastavené</translation>
    </message>
</context>
<context>
    <name>MainWindow</name>
    <message>
        <source>Jog X while held</source>
        <extracomment>Keys and what they do (translated where shown: QT_TRANSLATE_NOOP only marks them).</extracomment>
        <translation>Posuv v osi X, kým je kláves stlačený</translation>
    </message>
    <message>
        <source>Jog Y while held (two arrows at once = diagonal)</source>
        <translation>Posuv v osi Y, kým je kláves stlačený (dve šípky naraz = šikmo)</translation>
    </message>
    <message>
        <source>Jog Z while held, on machines with a Z axis</source>
        <translation>Posuv v osi Z, kým je kláves stlačený (stroje s osou Z)</translation>
    </message>
    <message>
        <source>Shift (held)</source>
        <translation>Shift (držaný)</translation>
    </message>
    <message>
        <source>Jog and move at the other speed</source>
        <translation>Posuv a pohyb druhou rýchlosťou</translation>
    </message>
    <message>
        <source>Stop everything, from anywhere in the window</source>
        <translation>Zastaviť všetko, odkiaľkoľvek v okne</translation>
    </message>
    <message>
        <source>Manual / Absolute / Relative / Dynamics / Link / Axes / G-code / Settings page</source>
        <translation>Stránka Manuálne / Absolútne / Relatívne / Dynamika / Spojenie / Osi / G-kód / Nastavenia</translation>
    </message>
    <message>
        <source>Open a job (File → Open job…)</source>
        <translation>Otvoriť úlohu (Súbor → Otvoriť úlohu…)</translation>
    </message>
    <message>
        <source>Run the job from a line you pick (Jobs → Run from…)</source>
        <translation>Spustiť úlohu od riadku, ktorý vyberiete (Úlohy → Spustiť od…)</translation>
    </message>
    <message>
        <source>Quit (stops the machine first)</source>
        <translation>Ukončiť (najprv zastaví stroj)</translation>
    </message>
    <message>
        <source>Show or hide the jobs dock</source>
        <translation>Zobraziť alebo skryť panel úloh</translation>
    </message>
    <message>
        <source>Show or hide the telemetry plots</source>
        <translation>Zobraziť alebo skryť grafy telemetrie</translation>
    </message>
    <message>
        <source>Show or hide the developer pane</source>
        <translation>Zobraziť alebo skryť vývojársky panel</translation>
    </message>
    <message>
        <source>Show or hide the macros (G-code machines)</source>
        <translation>Zobraziť alebo skryť makrá (stroje na G-kód)</translation>
    </message>
    <message>
        <source>Run macro 1 … 9 (G-code machines)</source>
        <translation>Spustiť makro 1 … 9 (stroje na G-kód)</translation>
    </message>
    <message>
        <source>This list</source>
        <translation>Tento prehľad</translation>
    </message>
    <message>
        <source>StepDeck — {0}</source>
        <extracomment>The operator chose another machine profile; the launcher rebuilds station and window. Where a language switch compiles its translation (None: the station&apos;s cache). This machine&apos;s own settings (arrow keys, link, skipped lines), apart from others&apos;. The box listing settings the station could not use (None: there were none).</extracomment>
        <translation>StepDeck — {0}</translation>
    </message>
    <message>
        <source>&amp;Manual</source>
        <extracomment>A page with motion controls: the motion lock turns it off. Adds a page button: its title, the page, its tooltip (both made again on a language switch). Every page with motion controls, for the motion lock. GRBL&apos;s $$ or the usb3 unit&apos;s EEPROM values (:mod:`widgets.panels.stored_settings`). The Dynamics page: the panel in a scroll area that only scrolls up and down.</extracomment>
        <translation>&amp;Manuálne</translation>
    </message>
    <message>
        <source>Hold-to-jog buttons, Home (Alt+M)</source>
        <translation>Tlačidlá posuvu (držať), referencia (Alt+M)</translation>
    </message>
    <message>
        <source>D&amp;rill</source>
        <translation>V&amp;ŕtačka</translation>
    </message>
    <message>
        <source>Command buttons, X/Y, terminal (Alt+R)</source>
        <translation>Tlačidlá príkazov, X/Y, terminál (Alt+R)</translation>
    </message>
    <message>
        <source>A&amp;xes</source>
        <translation>Osi (&amp;X)</translation>
    </message>
    <message>
        <source>Move by mm, step size, thread (Alt+X)</source>
        <translation>Posun o mm, mikrokrok, stúpanie závitu (Alt+X)</translation>
    </message>
    <message>
        <source>&amp;Absolute</source>
        <translation>&amp;Absolútne</translation>
    </message>
    <message>
        <source>Move to a target (Alt+A)</source>
        <translation>Nabehnúť na zadanú polohu (Alt+A)</translation>
    </message>
    <message>
        <source>&amp;Relative</source>
        <translation>&amp;Relatívne</translation>
    </message>
    <message>
        <source>Move by an increment (Alt+R)</source>
        <translation>Posunúť o prírastok (Alt+R)</translation>
    </message>
    <message>
        <source>&amp;G-code</source>
        <translation>&amp;G-kód</translation>
    </message>
    <message>
        <source>Console, pen, hold/resume/reset (Alt+G)</source>
        <translation>Konzola, pero, pozastavenie/pokračovanie/reset (Alt+G)</translation>
    </message>
    <message>
        <source>&amp;Dynamics</source>
        <translation>&amp;Dynamika</translation>
    </message>
    <message>
        <source>Device parameters (Alt+D)</source>
        <translation>Parametre zariadenia (Alt+D)</translation>
    </message>
    <message>
        <source>Se&amp;ttings</source>
        <translation>Nas&amp;tavenia</translation>
    </message>
    <message>
        <source>Stored settings: read, edit, snapshots (Alt+T)</source>
        <translation>Uložené nastavenia: čítanie, úpravy, zálohy (Alt+T)</translation>
    </message>
    <message>
        <source>&amp;Link</source>
        <translation>Spojenie (&amp;L)</translation>
    </message>
    <message>
        <source>Connect: emulator, serial port or BLE (Alt+L)</source>
        <translation>Pripojenie: emulátor, sériový port alebo BLE (Alt+L)</translation>
    </message>
    <message>
        <source>&amp;Colours</source>
        <translation>&amp;Farby</translation>
    </message>
    <message>
        <source>As the &amp;system</source>
        <translation>Podľa &amp;systému</translation>
    </message>
    <message>
        <source>&amp;Light</source>
        <translation>&amp;Svetlé</translation>
    </message>
    <message>
        <source>&amp;Dark</source>
        <translation>&amp;Tmavé</translation>
    </message>
    <message>
        <source>L&amp;anguage</source>
        <translation>&amp;Jazyk</translation>
    </message>
    <message>
        <source>Language: {0}</source>
        <translation>Jazyk: {0}</translation>
    </message>
    <message>
        <source>Frames from the device that failed to decode</source>
        <extracomment>How long a status-bar message stays (ms): long enough to read twice. The link state when the message shown was said (a link failure&apos;s message goes when the link is back).</extracomment>
        <translation>Rámce zo zariadenia, ktoré sa nepodarilo dekódovať</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Súbor</translation>
    </message>
    <message>
        <source>&amp;Open job…</source>
        <translation>&amp;Otvoriť úlohu…</translation>
    </message>
    <message>
        <source>&amp;Recent jobs</source>
        <translation>&amp;Nedávne úlohy</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Ukončiť</translation>
    </message>
    <message>
        <source>&amp;Machine</source>
        <translation>S&amp;troj</translation>
    </message>
    <message>
        <source>&amp;Connect</source>
        <translation>&amp;Pripojiť</translation>
    </message>
    <message>
        <source>&amp;Disconnect</source>
        <translation>&amp;Odpojiť</translation>
    </message>
    <message>
        <source>&amp;Stop</source>
        <translation>&amp;Zastaviť</translation>
    </message>
    <message>
        <source>&amp;Drop the queue</source>
        <translation>&amp;Zahodiť frontu príkazov</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Zobrazenie</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Pomocník</translation>
    </message>
    <message>
        <source>&amp;Keys</source>
        <translation>&amp;Klávesy</translation>
    </message>
    <message>
        <source>&amp;About StepDeck</source>
        <translation>&amp;O programe StepDeck</translation>
    </message>
    <message>
        <source>(none yet)</source>
        <translation>(zatiaľ žiadne)</translation>
    </message>
    <message>
        <source>&amp;Clear the list</source>
        <translation>&amp;Vymazať zoznam</translation>
    </message>
    <message>
        <source>{0}: not opened — the file is no longer there</source>
        <translation>{0}: neotvorené — súbor už neexistuje</translation>
    </message>
    <message>
        <source>A control station for small stepper machines: XY stages, a PCB drill, G-code plotters, the usb3 unit and the string-art winder.</source>
        <translation>Riadiaca stanica pre malé stroje s krokovými motormi: XY stolíky, vŕtačku plošných spojov, plotre na G-kód, jednotku usb3 a navíjačku pre string art.</translation>
    </message>
    <message>
        <source>Machine: {0}</source>
        <translation>Stroj: {0}</translation>
    </message>
    <message>
        <source>About StepDeck</source>
        <translation>O programe StepDeck</translation>
    </message>
    <message>
        <source>Arrows do not jog while a text or number field has focus: there they keep editing. Esc works from anywhere in the window and also closes an open menu; in a dialog (like this one) Esc closes the dialog only.</source>
        <translation>Keď je aktívne textové alebo číselné pole, šípky strojom nepohybujú, ale upravujú text. Esc funguje odkiaľkoľvek v okne a zavrie aj otvorenú ponuku; v dialógu (ako je tento) Esc iba zavrie dialóg.</translation>
    </message>
    <message>
        <source>StepDeck — keyboard shortcuts</source>
        <translation>StepDeck — klávesové skratky</translation>
    </message>
    <message>
        <source>Motion locked: {0}</source>
        <translation>Pohyb zablokovaný: {0}</translation>
    </message>
    <message>
        <source>Link {0}</source>
        <translation>Spojenie: {0}</translation>
    </message>
    <message numerus="yes">
        <source>rejected frames: %n</source>
        <translation>
            <numerusform>%n odmietnutý rámec</numerusform>
            <numerusform>%n odmietnuté rámce</numerusform>
            <numerusform>%n odmietnutých rámcov</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n settings could not be used; defaults are used instead</source>
        <translation>
            <numerusform>%n nastavenie sa nedalo použiť; platí predvolená hodnota</numerusform>
            <numerusform>%n nastavenia sa nedali použiť; platia predvolené hodnoty</numerusform>
            <numerusform>%n nastavení sa nedalo použiť; platia predvolené hodnoty</numerusform>
        </translation>
    </message>
    <message>
        <source>StepDeck — settings</source>
        <translation>StepDeck — nastavenia</translation>
    </message>
    <message>
        <source>Stopping every axis before closing…</source>
        <translation>Pred zatvorením zastavujem všetky osi…</translation>
    </message>
    <message>
        <source>Feed override -10 % / +10 %, on GRBL machines</source>
        <translation>Korekcia posuvu -10 % / +10 %, na strojoch s GRBL</translation>
    </message>
    <message>
        <source>Feed override -1 % / +1 %, on GRBL machines</source>
        <translation>Korekcia posuvu -1 % / +1 %, na strojoch s GRBL</translation>
    </message>
    <message>
        <source>Feed override back to 100 %, on GRBL machines</source>
        <translation>Korekcia posuvu späť na 100 %, na strojoch s GRBL</translation>
    </message>
    <message>
        <source>Rapid override 100 → 50 → 25 %, on GRBL machines</source>
        <translation>Korekcia rýchloposuvu 100 → 50 → 25 %, na strojoch s GRBL</translation>
    </message>
    <message>
        <source>&amp;Overrides</source>
        <translation>&amp;Korekcie</translation>
    </message>
</context>
<context>
    <name>ManualPanel</name>
    <message>
        <source>Hold to jog {0}  (keys: {1}; Shift = other speed)</source>
        <extracomment>(row, column) in the cross → (dx, dy, label, key hint); ``{0}``/``{1}`` are the profile&apos;s first two axes (X and Y on a plotter, A and X on the string-art winder). The arrow keys&apos; step was chosen (0: continuous): the window stores it.</extracomment>
        <translation>Držaním posúvať {0}  (klávesy: {1}; Shift = druhá rýchlosť)</translation>
    </message>
    <message>
        <source>continuous (hold)</source>
        <extracomment>Why the jog buttons are off while the machine itself may move (a job under way). Buttons shown pressed for a held arrow key (never one the mouse holds). The pad and the arrow-key choice, left out on a machine that cannot jog.</extracomment>
        <translation>plynulo (držať)</translation>
    </message>
    <message>
        <source>{0} {1} per tap</source>
        <translation>{0} {1} na stlačenie</translation>
    </message>
    <message>
        <source>What a tap of an arrow key does: jog while held, or move one step (never past the travel)</source>
        <translation>Čo urobí stlačenie šípky: posuv počas držania, alebo jeden krok (nikdy za hranicu posuvu)</translation>
    </message>
    <message>
        <source>Arrow keys:</source>
        <translation>Šípky:</translation>
    </message>
    <message>
        <source>Home all</source>
        <translation>Referencia všetkých osí</translation>
    </message>
    <message>
        <source>Home every axis: the machine&apos;s home command does them all</source>
        <translation>Referenčný posuv všetkých osí: príkaz stroja ich presunie všetky</translation>
    </message>
    <message>
        <source>Home {0}</source>
        <translation>Referencia {0}</translation>
    </message>
    <message>
        <source>Seek the {0} home switch and set {0} = 0</source>
        <translation>Nájsť referenčný spínač osi {0} a nastaviť {0} = 0</translation>
    </message>
    <message>
        <source>Hold to jog {0} up  (key: {1})</source>
        <translation>Držaním posúvať {0} hore  (kláves: {1})</translation>
    </message>
    <message>
        <source>Hold to jog {0} down  (key: {1})</source>
        <translation>Držaním posúvať {0} dole  (kláves: {1})</translation>
    </message>
    <message>
        <source>Jogging locked: {0}</source>
        <translation>Ručný posuv zablokovaný: {0}</translation>
    </message>
</context>
<context>
    <name>MotionGate</name>
    <message>
        <source>Motion refused: {0}</source>
        <translation>Pohyb odmietnutý: {0}</translation>
    </message>
    <message>
        <source>there is no axis {0}</source>
        <extracomment>Targets this close past a limit are rounding (a move to exactly the travel end).</extracomment>
        <translation>os {0} neexistuje</translation>
    </message>
    <message>
        <source>{0} {1} is not a position</source>
        <translation>{0} {1} nie je poloha</translation>
    </message>
    <message>
        <source>{0} {1} {2} is outside the travel {3}…{4} {2}</source>
        <translation>{0} {1} {2} je mimo pojazd {3}…{4} {2}</translation>
    </message>
    <message>
        <source>{0} {1} is not a distance</source>
        <translation>{0} {1} nie je vzdialenosť</translation>
    </message>
    <message>
        <source>{0} {1} from {2}: {3}</source>
        <translation>{0} {1} z {2}: {3}</translation>
    </message>
    <message>
        <source>the motors are not released: {0}</source>
        <translation>motory nie sú uvoľnené: {0}</translation>
    </message>
    <message>
        <source>the work zero stays: {0}</source>
        <translation>pracovná nula zostáva: {0}</translation>
    </message>
</context>
<context>
    <name>NumberField</name>
    <message>
        <source>Allowed: {0}</source>
        <extracomment>A number being typed: optional sign, digits, one decimal point or comma, digits. The note under a page&apos;s fields that says which one is wrong. An acceptable value was committed: Enter, focus out or an Up/Down step. The field turned acceptable or not acceptable (its buttons follow this). What follows the unit, derived from the value (e.g. a current scale&apos;s amperes).</extracomment>
        <translation>Povolené: {0}</translation>
    </message>
    <message>
        <source>Not a number</source>
        <translation>Nie je číslo</translation>
    </message>
    <message>
        <source>Empty: type a number</source>
        <translation>Prázdne: zadajte číslo</translation>
    </message>
    <message>
        <source>{0} is outside {1}</source>
        <translation>{0} je mimo {1}</translation>
    </message>
    <message numerus="yes">
        <source>At most %n decimal(s)</source>
        <translation>
            <numerusform>Najviac %n desatinné miesto</numerusform>
            <numerusform>Najviac %n desatinné miesta</numerusform>
            <numerusform>Najviac %n desatinných miest</numerusform>
        </translation>
    </message>
    <message>
        <source>Whole numbers only</source>
        <translation>Len celé čísla</translation>
    </message>
    <message>
        <source>Not sent — {0}</source>
        <translation>Neodoslané — {0}</translation>
    </message>
    <message>
        <source>Disabled: {0}</source>
        <translation>Nedostupné: {0}</translation>
    </message>
</context>
<context>
    <name>Operation</name>
    <message>
        <source>move</source>
        <translation>pohyb</translation>
    </message>
    <message>
        <source>drill</source>
        <translation>vŕtanie</translation>
    </message>
    <message>
        <source>pen up</source>
        <translation>pero hore</translation>
    </message>
    <message>
        <source>pen down</source>
        <translation>pero dole</translation>
    </message>
    <message>
        <source>wait</source>
        <translation>čakanie</translation>
    </message>
    <message>
        <source>comment</source>
        <translation>poznámka</translation>
    </message>
    <message>
        <source>gcode</source>
        <translation>G-kód</translation>
    </message>
    <message>
        <source>move to {0}</source>
        <translation>presun na {0}</translation>
    </message>
</context>
<context>
    <name>OverrideBox</name>
    <message>
        <source>Overrides</source>
        <translation>Korekcie</translation>
    </message>
    <message>
        <source>Feed override -10 %</source>
        <translation>Korekcia posuvu -10 %</translation>
    </message>
    <message>
        <source>Feed override -1 %</source>
        <translation>Korekcia posuvu -1 %</translation>
    </message>
    <message>
        <source>Feed override +1 %</source>
        <translation>Korekcia posuvu +1 %</translation>
    </message>
    <message>
        <source>Feed override +10 %</source>
        <translation>Korekcia posuvu +10 %</translation>
    </message>
    <message>
        <source>100 %</source>
        <translation>100 %</translation>
    </message>
    <message>
        <source>Feed override back to 100 %</source>
        <translation>Korekcia posuvu späť na 100 %</translation>
    </message>
    <message>
        <source>{0} %</source>
        <translation>{0} %</translation>
    </message>
    <message>
        <source>Rapid (G0) at {0} %</source>
        <translation>Rýchloposuv (G0) na {0} %</translation>
    </message>
    <message>
        <source>Feed</source>
        <translation>Posuv</translation>
    </message>
    <message>
        <source>Rapid</source>
        <translation>Rýchloposuv</translation>
    </message>
    <message>
        <source>Rapid override 100 → 50 → 25 %</source>
        <translation>Korekcia rýchloposuvu 100 → 50 → 25 %</translation>
    </message>
</context>
<context>
    <name>Overrides</name>
    <message>
        <source>Override not sent: {0}</source>
        <extracomment>Status reports after the bytes before their effect is judged (see the module). Rounds of sending what is missing before the station gives up and says so: from 10 to 200 % a step of 10 and one of 1 at a time, on a board that merged the whole first burst. The firmware has GRBL&apos;s overrides (the registry says; False until it does). The last ``Ov:`` heard; None before any (or after a reset: 100 % then).</extracomment>
        <translation>Korekcia neodoslaná: {0}</translation>
    </message>
    <message>
        <source>this machine&apos;s firmware has no feed or rapid override</source>
        <translation>firmvér tohto stroja nemá korekciu posuvu ani rýchloposuvu</translation>
    </message>
    <message>
        <source>not connected</source>
        <translation>nepripojené</translation>
    </message>
    <message>
        <source>a feed override of {0} % is outside {1}…{2} %</source>
        <translation>korekcia posuvu {0} % je mimo {1}…{2} %</translation>
    </message>
    <message>
        <source>a rapid override of {0} % is none of 25, 50 and 100 %</source>
        <translation>korekcia rýchloposuvu {0} % nie je 25, 50 ani 100 %</translation>
    </message>
    <message>
        <source>The board did not take the override: feed {0} %, rapid {1} % asked</source>
        <translation>Doska korekciu neprijala: požadovaný posuv {0} %, rýchloposuv {1} %</translation>
    </message>
</context>
<context>
    <name>PenWatch</name>
    <message>
        <source>up</source>
        <translation>hore</translation>
    </message>
    <message>
        <source>down</source>
        <translation>dole</translation>
    </message>
    <message>
        <source>the spindle (the pen servo) on, clockwise (A:S)</source>
        <translation>vreteno (servo pera) zapnuté, v smere hodinových ručičiek (A:S)</translation>
    </message>
    <message>
        <source>the spindle (the pen servo) on, counter-clockwise (A:C)</source>
        <translation>vreteno (servo pera) zapnuté, proti smeru hodinových ručičiek (A:C)</translation>
    </message>
    <message>
        <source>the spindle (the pen servo) off</source>
        <translation>vreteno (servo pera) vypnuté</translation>
    </message>
    <message>
        <source>the board&apos;s reset</source>
        <translation>resetu dosky</translation>
    </message>
    <message>
        <source>Machine stopped: the pen is {0} after {1} ran (pen {2} sent), but the board did not report the change it makes; the line it got was not the line sent</source>
        <translation>Stroj zastavený: pero je {0} po vykonaní {1} (odoslané: pero {2}), ale doska zmenu, ktorú ten riadok spôsobí, nenahlásila; dostala iný riadok, než aký bol odoslaný</translation>
    </message>
    <message>
        <source>Machine stopped: the pen is {0} after {1} ran (pen {2} sent): the board reports {3}</source>
        <translation>Stroj zastavený: pero je {0} po vykonaní {1} (odoslané: pero {2}): doska hlási {3}</translation>
    </message>
    <message>
        <source>{0} counted as answered while the moves before it still ran (GRBL answers a pen line only once they are done): a line or an answer was lost, changed or repeated on the way.</source>
        <translation>{0} bol započítaný ako zodpovedaný, kým pohyby pred ním ešte bežali (GRBL odpovedá na riadok pera až po ich dokončení): riadok alebo odpoveď sa cestou stratili, zmenili alebo zopakovali.</translation>
    </message>
</context>
<context>
    <name>QPlatformTheme</name>
    <message>
        <source>OK</source>
        <extracomment>The languages offered, by code, each named in itself (a user who cannot read the current language still finds their own). Compiling one file takes a few tens of milliseconds; more means something is wrong. Qt&apos;s standard buttons, which Slovak&apos;s ``qtbase`` leaves in English (it has them only under an older context): the station&apos;s own translation says them in both languages.</extracomment>
        <translation>OK</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Zrušiť</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Zavrieť</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Uložiť</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Otvoriť</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Použiť</translation>
    </message>
    <message>
        <source>Discard</source>
        <translation>Zahodiť</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Obnoviť</translation>
    </message>
    <message>
        <source>Help</source>
        <translation>Pomocník</translation>
    </message>
    <message>
        <source>&amp;Yes</source>
        <translation>Án&amp;o</translation>
    </message>
    <message>
        <source>&amp;No</source>
        <translation>&amp;Nie</translation>
    </message>
</context>
<context>
    <name>RegistrationBar</name>
    <message>
        <source>The bottom side of a double-sided board: the job mirrored about its own extent</source>
        <translation>Spodná strana obojstrannej dosky: úloha zrkadlená v rámci svojho rozsahu</translation>
    </message>
    <message>
        <source>Top side</source>
        <translation>Horná strana</translation>
    </message>
    <message>
        <source>Bottom, mirrored in X</source>
        <translation>Spodná, zrkadlená v X</translation>
    </message>
    <message>
        <source>Bottom, mirrored in Y</source>
        <translation>Spodná, zrkadlená v Y</translation>
    </message>
    <message>
        <source>Holes</source>
        <extracomment>At most this many reference holes (three: least squares with a residual). The operator wants to click reference ``k`` (0-based) in the preview; -1: stop picking. The job as its file says (what registration transforms; Clear goes back to it). How the loaded job was put on the board (side, registration).</extracomment>
        <translation>Otvory</translation>
    </message>
    <message>
        <source>Register on holes: two (or three) reference holes of the job</source>
        <translation>Zameranie podľa otvorov: dva (alebo tri) referenčné otvory úlohy</translation>
    </message>
    <message>
        <source>A reference hole: its number in drilling order</source>
        <translation>Referenčný otvor: jeho číslo v poradí vŕtania</translation>
    </message>
    <message>
        <source>Pick</source>
        <translation>Vybrať</translation>
    </message>
    <message>
        <source>Then click the hole in the preview</source>
        <translation>Potom kliknite na otvor v náhľade</translation>
    </message>
    <message>
        <source>Here</source>
        <translation>Tu</translation>
    </message>
    <message>
        <source>The tool stands over this hole on the board: take its position</source>
        <translation>Nástroj stojí nad týmto otvorom na doske: prevziať jeho polohu</translation>
    </message>
    <message>
        <source>3 points</source>
        <translation>3 body</translation>
    </message>
    <message>
        <source>A third reference hole: averaged in, and how far the points disagree shown</source>
        <translation>Tretí referenčný otvor: započíta sa do priemeru a ukáže, nakoľko sa body rozchádzajú</translation>
    </message>
    <message>
        <source>Register</source>
        <translation>Zamerať</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Vymazať</translation>
    </message>
    <message>
        <source>cannot mirror: {0}</source>
        <translation>nedá sa zrkadliť: {0}</translation>
    </message>
    <message>
        <source>reference {0} is hole {1} (X{2} Y{3} in the job)</source>
        <translation>referenčný bod {0} je otvor {1} (X{2} Y{3} v úlohe)</translation>
    </message>
    <message>
        <source>reference {0} (hole {1}) at X{2} Y{3}</source>
        <translation>referencia {0} (otvor {1}) na X{2} Y{3}</translation>
    </message>
    <message>
        <source>registration refused: {0}</source>
        <translation>zameranie odmietnuté: {0}</translation>
    </message>
    <message>
        <source>registered: {0}</source>
        <translation>zamerané: {0}</translation>
    </message>
    <message>
        <source>the three points agree within {0} mm</source>
        <translation>tri body sa zhodujú do {0} mm</translation>
    </message>
    <message>
        <source>warning: {0}</source>
        <translation>upozornenie: {0}</translation>
    </message>
</context>
<context>
    <name>RelativePanel</name>
    <message>
        <source>Move by</source>
        <translation>Posunúť o</translation>
    </message>
    <message>
        <source>{0} increment (Esc stops)</source>
        <translation>Prírastok {0} (Esc zastaví)</translation>
    </message>
    <message>
        <source>Move {0} back by the increment</source>
        <translation>Posunúť {0} o prírastok späť</translation>
    </message>
    <message>
        <source>Move {0} forward by the increment</source>
        <translation>Posunúť {0} o prírastok vpred</translation>
    </message>
    <message>
        <source>{0} increment</source>
        <translation>Prírastok {0}</translation>
    </message>
</context>
<context>
    <name>ResumeChoicePanel</name>
    <message>
        <source>Sent, but not proven run: pick the first line the drawing does not show yet</source>
        <extracomment>The rows&apos; data role: the operation index resuming there starts with. Rows listed at most (a resume from a checkpoint offers a window of lines).</extracomment>
        <translation>Odoslané, ale vykonanie nie je preukázané: vyberte prvý riadok, ktorý na kresbe ešte nie je</translation>
    </message>
    <message>
        <source>Resume from the chosen line</source>
        <translation>Pokračovať od zvoleného riadku</translation>
    </message>
    <message>
        <source>The machine goes there with the pen up, then carries on</source>
        <translation>Stroj tam prejde so zdvihnutým perom a potom pokračuje</translation>
    </message>
    <message>
        <source>from op {0}: {1}  {2}</source>
        <translation>od op. {0}: {1}  {2}</translation>
    </message>
    <message>
        <source>none of them: the job is at its end</source>
        <translation>žiadna z nich: úloha je na konci</translation>
    </message>
</context>
<context>
    <name>RotationCross</name>
    <message>
        <source>Platform rotation relative to the last Zero (counter-clockwise positive)</source>
        <extracomment>Curve colours per axis (X, Y, Z, then whatever else a profile has). The least height of the three plots together, in pixels (a 1280 x 800 window must fit). The width of the caption (title, unit and key) beside each plot, in pixels. The least height a plot&apos;s vertical range shows (in its unit: mm, mm/s, V…).</extracomment>
        <translation>Natočenie plošiny voči poslednému vynulovaniu (kladne proti smeru hodinových ručičiek)</translation>
    </message>
    <message>
        <source>rotation
not plotted</source>
        <translation>natočenie
sa nevykresľuje</translation>
    </message>
</context>
<context>
    <name>Session</name>
    <message>
        <source>{0} has no {1}</source>
        <translation>{0} nemá {1}</translation>
    </message>
    <message>
        <source>Jog refused: {0}</source>
        <translation>Ručný posuv odmietnutý: {0}</translation>
    </message>
    <message>
        <source>Motion refused: {0}</source>
        <translation>Pohyb odmietnutý: {0}</translation>
    </message>
    <message>
        <source>jogging</source>
        <extracomment>A held jog with no sign for this long that the key or button is still held ends (the station&apos;s dead-man). Longer than a keyboard&apos;s auto-repeat delay (0.25 to 0.66 s), whose repeats are the sign for a key; a held button is polled for it. A held jog ended without a release (dead-man or travel end): forget what is held. Since when the device has been silent with its port open, once that was a lost link (None: it is not); and whether it has answered since. Whether a late tick&apos;s lateness is the station&apos;s own, not counted as the device&apos;s silence (set by dialects whose ticks come from a real-time timer).</extracomment>
        <translation>ručný posuv</translation>
    </message>
    <message>
        <source>stop command</source>
        <translation>príkaz zastavenia</translation>
    </message>
    <message>
        <source>{0} is at the end of its travel</source>
        <translation>{0} je na konci rozsahu pojazdu</translation>
    </message>
    <message>
        <source>relative moves</source>
        <translation>relatívne pohyby</translation>
    </message>
    <message>
        <source>absolute moves</source>
        <translation>absolútne pohyby</translation>
    </message>
    <message>
        <source>The device is silent ({0}){1}; asking it every {2} s</source>
        <extracomment>Seconds a device has to give its first valid reply before the operator is told. Bytes of unrecognised replies kept to tell which machine is there instead. A device silent with its port open, or not answering since the link opened, is asked its dialect&apos;s harmless question this often: the devices that speak only when asked (usb3, the drill) would otherwise never be heard again once the line works. A tick this much later than its period means the station itself was not running (a busy computer, a stalled event loop): that time is not counted as the device&apos;s silence. :meth:`AnswerWatch._recovery_verdict`&apos;s &quot;not yet&quot;. The device answers again after a silence with its port open: None when its state is intact (nothing can have been lost), else what does not match (a reset, a position).</extracomment>
        <translation>Zariadenie mlčí ({0}){1}; pýtam sa ho každých {2} s</translation>
    </message>
    <message>
        <source>the device answers again; checking it…</source>
        <translation>zariadenie opäť odpovedá; kontrolujem ho…</translation>
    </message>
    <message>
        <source>The device answers again ({0} s after it was given up), its state intact</source>
        <translation>Zariadenie opäť odpovedá ({0} s potom, čo bolo vzdané), jeho stav je neporušený</translation>
    </message>
    <message>
        <source>The device answers again ({0} s after it was given up), but {1}</source>
        <translation>Zariadenie opäť odpovedá ({0} s potom, čo bolo vzdané), ale {1}</translation>
    </message>
    <message>
        <source>; its replies sound like {0}</source>
        <translation>; jeho odpovede pripomínajú {0}</translation>
    </message>
    <message>
        <source>no answer: is this a {0}? Check the profile, baud and port{1}</source>
        <translation>bez odpovede: je to naozaj {0}? Skontrolujte profil, rýchlosť a port{1}</translation>
    </message>
    <message>
        <source>Axis {0}: device refused a command</source>
        <extracomment>Telemetry keys and the factor from wire units to displayed units.</extracomment>
        <translation>Os {0}: zariadenie odmietlo príkaz</translation>
    </message>
    <message>
        <source>Link lost: {0}</source>
        <translation>Spojenie stratené: {0}</translation>
    </message>
</context>
<context>
    <name>Settings</name>
    <message>
        <source>Setting {0} in {1} was {2}; it should be {3}, so the default is used</source>
        <extracomment>Baud rates a serial port can be asked for (pyserial&apos;s own bounds on Linux). The stage&apos;s command frame period, as ``--period`` and the profiles allow it. Window geometry and dock layout blobs are a few hundred bytes; more is not ours. Suffix of the copy kept of a settings file Qt could not read. What the value must be, in words for the warning (&quot;an integer within 20…1000&quot;). The stored value as a ``T``; raises :class:`BadValue` for anything else. The page shown; the window has fewer, and checks the index again against its own count. Excellon steps the jobs dock offers, in inches. The jobs dock&apos;s reading options, by option name. The drill&apos;s timing constants as the operator set them in the station (FIDELITY S2-06), by constant name; absent: the profile&apos;s. The drill&apos;s conversion constants as the teacher set them (FIDELITY S2-42), kept per machine profile (``machines/&lt;profile&gt;/drill_conversion/…``); absent: the profile&apos;s. What one tap of an arrow key moves (mm, or degrees on a rotary axis); 0: held, continuous. How many job files File → Recent jobs lists. The job files opened last, newest first (&quot;&quot; where there is none). The window&apos;s colours: as the desktop says, or always light or dark. The language: the system locale&apos;s (English where it is none of these) or a fixed one. The jobs dock&apos;s options that concern the machine: stored per profile. Every value kept per machine profile; each key here is also where a file from before kept it for every machine (read once, then moved: see ``StationSettings._migrate``). Where the per-machine values live: ``machines/&lt;profile&gt;/&lt;key&gt;``. Every key, for the tests (and for anyone wondering what the file may hold). The warnings, translated when they are taken (see StationSettings.take_warnings).</extracomment>
        <translation>Nastavenie {0} v súbore {1} malo hodnotu {2}; má byť {3}, preto sa použije predvolená hodnota</translation>
    </message>
    <message>
        <source>Settings file {0} is malformed: defaults are used</source>
        <translation>Súbor nastavení {0} je poškodený: použijú sa predvolené hodnoty</translation>
    </message>
    <message>
        <source>Settings file {0} is malformed: defaults are used; a copy is kept as {1}</source>
        <translation>Súbor nastavení {0} je poškodený: použijú sa predvolené hodnoty; jeho kópia je uložená ako {1}</translation>
    </message>
    <message>
        <source>Settings file {0} is not readable: defaults are used</source>
        <translation>Súbor nastavení {0} sa nedá prečítať: použijú sa predvolené hodnoty</translation>
    </message>
</context>
<context>
    <name>SettingsAccess</name>
    <message>
        <source>the machine is stopping</source>
        <extracomment>The lines&apos; origin in the session (the frame log and the console show it). GRBL states in which it takes ``$$`` and ``$N=``, as the station allows them. ``$N=`` lines heard since the last ``$$`` sent (GRBL lists them before its ok). The settings lines sent and not answered, oldest first. The device&apos;s refusals of this write, by key.</extracomment>
        <translation>stroj zastavuje</translation>
    </message>
    <message>
        <source>the board is {0}: settings wait until it stands idle</source>
        <translation>doska je v stave {0}: nastavenie počká, kým bude v pokoji</translation>
    </message>
    <message>
        <source>not heard from yet</source>
        <translation>zatiaľ neozvala</translation>
    </message>
    <message>
        <source>lines sent before are still being run</source>
        <translation>skôr odoslané riadky sa ešte vykonávajú</translation>
    </message>
    <message>
        <source>{0} was not sent</source>
        <translation>{0} nebolo odoslané</translation>
    </message>
    <message>
        <source>$$ refused: error {0}, {1}</source>
        <translation>$$ odmietnuté: chyba {0}, {1}</translation>
    </message>
    <message>
        <source>{0}: refused, error {1}, {2}</source>
        <translation>{0}: odmietnuté, chyba {1}, {2}</translation>
    </message>
    <message>
        <source>the board was reset before it answered</source>
        <translation>doska bola resetovaná skôr, než odpovedala</translation>
    </message>
    <message>
        <source>not connected</source>
        <extracomment>&quot;read&quot; or &quot;write&quot;. The values the device read back as written (a write), or every value read. Why a value was not written, or why the read failed (empty: all went well). :attr:`values` changed (a read, a verified write, a report nobody asked for). A read or write ended: its :class:`Outcome`. What the settings are called in the window and in snapshots (&quot;grbl&quot;, &quot;usb3-eeprom&quot;). What the device last said it holds, by key. The last read or write&apos;s outcome (None before any). A read or write under way (&quot;read&quot;/&quot;write&quot;), None when idle. What a write under way asked for. The firmware version the device said it runs (a snapshot records it), None until it says, and for a device with no way to say it (the usb3 unit&apos;s wire has none).</extracomment>
        <translation>nepripojené</translation>
    </message>
    <message>
        <source>a job is running</source>
        <translation>beží úloha</translation>
    </message>
    <message>
        <source>the machine is moving</source>
        <translation>stroj sa pohybuje</translation>
    </message>
    <message>
        <source>{0}: no such setting</source>
        <translation>{0}: také nastavenie nie je</translation>
    </message>
    <message>
        <source>not sent</source>
        <translation>neodoslané</translation>
    </message>
    <message>
        <source>nothing to write</source>
        <translation>nie je čo zapísať</translation>
    </message>
    <message>
        <source>a read is under way</source>
        <translation>prebieha čítanie</translation>
    </message>
    <message>
        <source>a write is under way</source>
        <translation>prebieha zápis</translation>
    </message>
    <message>
        <source>{0}: {1} was written, the device keeps {2}</source>
        <translation>{0}: zapísané {1}, zariadenie drží {2}</translation>
    </message>
    <message>
        <source>the link went down before the device answered</source>
        <translation>spojenie spadlo skôr, než zariadenie odpovedalo</translation>
    </message>
</context>
<context>
    <name>StageParameter</name>
    <message>
        <source>Fast speed</source>
        <extracomment>The parameters&apos; labels as app.machines.stage.parameters names them, for lupdate.</extracomment>
        <translation>Rýchla rýchlosť</translation>
    </message>
    <message>
        <source>Slow speed</source>
        <translation>Pomalá rýchlosť</translation>
    </message>
    <message>
        <source>Acceleration</source>
        <translation>Zrýchlenie</translation>
    </message>
    <message>
        <source>Start speed</source>
        <translation>Rozbehová rýchlosť</translation>
    </message>
    <message>
        <source>Run current (IRUN)</source>
        <translation>Prúd za chodu (IRUN)</translation>
    </message>
    <message>
        <source>Hold current (IHOLD)</source>
        <translation>Prídržný prúd (IHOLD)</translation>
    </message>
    <message>
        <source>Microsteps per step</source>
        <translation>Mikrokrokov na krok</translation>
    </message>
    <message>
        <source>Screw lead</source>
        <translation>Stúpanie skrutky</translation>
    </message>
    <message>
        <source>Full steps per rev</source>
        <translation>Celých krokov na otáčku</translation>
    </message>
    <message>
        <source>Travel (soft limit)</source>
        <translation>Posuv (softvérový limit)</translation>
    </message>
    <message>
        <source>Encoder position</source>
        <translation>Poloha enkodéra</translation>
    </message>
    <message>
        <source>{0} must be within {1}…{2} {3}</source>
        <translation>{0} musí byť v rozsahu {1}…{2} {3}</translation>
    </message>
    <message>
        <source>{0} must be a power of two</source>
        <translation>{0} musí byť mocnina dvoch</translation>
    </message>
</context>
<context>
    <name>StageSession</name>
    <message>
        <source>Not written: {0} {1}</source>
        <extracomment>Echoes counted past a MOVE_ABS&apos;s frame before one is believed to answer a later frame. Echoes come back in order, one per valid frame, so a lost frame or echo only makes the count lag; the margin of one more covers a duplicated or stale echo. Axes whose held jog was turned into a move to the travel end (+1/-1, 0: none). Every echoed position is judged against the moves sent (stopped when off them). Frames sent and echoes received since the link opened (see _check_moves). Per axis: the last MOVE_ABS sent and the frame count it went out with, until an echo of a later frame shows whether the stage received it.</extracomment>
        <translation>Nezapísané: {0} {1}</translation>
    </message>
    <message>
        <source>{0} jog ends before the travel&apos;s end, at {1} mm</source>
        <extracomment>What the info panel shows; each is asked for at least once a second. Until the stage&apos;s own dynamics are read: its documented defaults (docs/protocols.md §1.4). Periods between a frame leaving and its effect being seen (frame out, echo back), on top of the braking distance when a jog is turned into a stop at the travel end. A jog stopped at the travel&apos;s end stops this far inside it: the stage&apos;s end switches sit at the travel&apos;s ends, and a jog is to stop before them, not on them.</extracomment>
        <translation>Ručný posuv {0} končí pred koncom pojazdu, na {1} mm</translation>
    </message>
    <message>
        <source>nothing it reports shows whether it was switched off meanwhile</source>
        <translation>z ničoho, čo hlási, nie je poznať, či bolo medzitým vypnuté</translation>
    </message>
    <message>
        <source>{0} {1}: refused, the device keeps {2}</source>
        <translation>{0} {1}: odmietnuté, zariadenie ponecháva {2}</translation>
    </message>
</context>
<context>
    <name>StageWords</name>
    <message>
        <source>position</source>
        <extracomment>What an echo packet&apos;s TYPE says its DATA holds, in words (docs/protocols.md §1.3).</extracomment>
        <translation>poloha</translation>
    </message>
    <message>
        <source>velocity</source>
        <translation>rýchlosť</translation>
    </message>
    <message>
        <source>none</source>
        <extracomment>Subscriber variables in words (docs/protocols.md §1.5).</extracomment>
        <translation>žiadna</translation>
    </message>
    <message>
        <source>battery voltage</source>
        <translation>napätie batérie</translation>
    </message>
    <message>
        <source>battery charge</source>
        <translation>nabitie batérie</translation>
    </message>
    <message>
        <source>charging current</source>
        <translation>nabíjací prúd</translation>
    </message>
    <message>
        <source>board temperature</source>
        <translation>teplota dosky</translation>
    </message>
    <message>
        <source>rotation</source>
        <translation>natočenie</translation>
    </message>
    <message>
        <source>yaw rate</source>
        <translation>rýchlosť otáčania</translation>
    </message>
    <message>
        <source>device flags</source>
        <translation>príznaky zariadenia</translation>
    </message>
    <message>
        <source>X encoder</source>
        <translation>enkodér X</translation>
    </message>
    <message>
        <source>Y encoder</source>
        <translation>enkodér Y</translation>
    </message>
    <message>
        <source>firmware version</source>
        <translation>verzia firmvéru</translation>
    </message>
    <message>
        <source>rejected frames</source>
        <translation>odmietnuté rámce</translation>
    </message>
    <message>
        <source>unknown subscriber</source>
        <translation>neznámy odberateľ</translation>
    </message>
    <message>
        <source>charger</source>
        <extracomment>A field as a widget or a test hands it over: text typed or chosen, or a number. The device flags&apos; bits in words.</extracomment>
        <translation>nabíjačka</translation>
    </message>
    <message>
        <source>USB</source>
        <translation>USB</translation>
    </message>
    <message>
        <source>low battery</source>
        <translation>slabá batéria</translation>
    </message>
    <message>
        <source>sleeping</source>
        <translation>spí</translation>
    </message>
    <message>
        <source>data session</source>
        <translation>dátová relácia</translation>
    </message>
    <message>
        <source>slow</source>
        <translation>pomaly</translation>
    </message>
    <message>
        <source>fast</source>
        <translation>rýchlo</translation>
    </message>
    <message>
        <source>off</source>
        <translation>vyp</translation>
    </message>
    <message>
        <source>on</source>
        <translation>zap</translation>
    </message>
    <message>
        <source>pos</source>
        <translation>poloha</translation>
    </message>
    <message>
        <source>vel</source>
        <translation>rýchlosť</translation>
    </message>
</context>
<context>
    <name>StaticPanel</name>
    <message>
        <source>Fast</source>
        <translation>Rýchlo</translation>
    </message>
    <message>
        <source>Jog and move at the fast speed (hold Shift for slow)</source>
        <translation>Posuv a pohyb rýchlou rýchlosťou (so Shiftom pomaly)</translation>
    </message>
    <message>
        <source>Slow</source>
        <translation>Pomaly</translation>
    </message>
    <message>
        <source>Jog and move at the slow speed (hold Shift for fast)</source>
        <translation>Posuv a pohyb pomalou rýchlosťou (so Shiftom rýchlo)</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Rýchlosť</translation>
    </message>
    <message>
        <source>Shift held: slow</source>
        <translation>Shift držaný: pomaly</translation>
    </message>
    <message>
        <source>Shift held: fast</source>
        <translation>Shift držaný: rýchlo</translation>
    </message>
    <message>
        <source>Wake</source>
        <translation>Zobudiť</translation>
    </message>
    <message>
        <source>Sleep</source>
        <translation>Uspať</translation>
    </message>
    <message>
        <source>Wake the machine: motors on, motion controls unlocked</source>
        <translation>Zobudiť stroj: motory zapnuté, ovládanie pohybu odomknuté</translation>
    </message>
    <message>
        <source>Put the machine to sleep: motors off, motion controls locked until Wake</source>
        <translation>Uspať stroj: motory vypnuté, ovládanie pohybu zamknuté až do Zobudiť</translation>
    </message>
</context>
<context>
    <name>Station</name>
    <message>
        <source>Stopping every axis before closing the link…</source>
        <extracomment>The longest Disconnect or closing the window waits for the device to confirm the stop: the stage brakes from its default 10 mm/s at 20 mm/s² in 0.5 s, and says so in its next echo; a G-code board&apos;s hold takes about as long. How often the wait looks at the device&apos;s reports (in real time). A link was closed on the operator&apos;s word (after the stop, when one was awaited). The drill&apos;s timing constants changed (:meth:`set_drill_timing`): estimates are stale. The drill&apos;s conversion constants changed (:meth:`set_drill_conversion`): a loaded job is read again with them. How a job&apos;s millimetres become the drill&apos;s microsteps (FIDELITY S2-42): the profile&apos;s until the teacher changes them. Station-clock time by which the device must have confirmed the stop, while waiting.</extracomment>
        <translation>Pred ukončením spojenia zastavujem všetky osi…</translation>
    </message>
    <message>
        <source>The link went before the stop was confirmed; closed</source>
        <translation>Spojenie spadlo skôr, než bolo zastavenie potvrdené; ukončené</translation>
    </message>
    <message>
        <source>Every axis stopped; link closed</source>
        <translation>Všetky osi stoja; spojenie ukončené</translation>
    </message>
    <message>
        <source>The device did not confirm the stop within {0} s; link closed anyway — check that the machine stands</source>
        <translation>Zariadenie nepotvrdilo zastavenie do {0} s; spojenie napriek tomu ukončené — skontrolujte, že stroj stojí</translation>
    </message>
    <message>
        <source>Conversion constants not changed: {0}</source>
        <translation>Prevodové konštanty nezmenené: {0}</translation>
    </message>
    <message>
        <source>reconnecting to {0}…</source>
        <translation>znova sa pripájam k {0}…</translation>
    </message>
    <message>
        <source>{0} — retrying in {1} s</source>
        <translation>{0} — nový pokus o {1} s</translation>
    </message>
    <message>
        <source>Internal error ({0}: {1}); machine stopped</source>
        <extracomment>``stepdeck NAME …`` runs module&apos;s ``main(argv) -&gt; int`` with the rest of the command line. Qt platforms with no screen to ask on: there, a missing choice is refused, not guessed.</extracomment>
        <translation>Vnútorná chyba ({0}: {1}); stroj zastavený</translation>
    </message>
</context>
<context>
    <name>StopCaption</name>
    <message>
        <source>STOP</source>
        <translation>STOP</translation>
    </message>
    <message>
        <source>Stop every axis now (Esc, from anywhere in the window)</source>
        <translation>Okamžite zastaviť všetky osi (Esc, odkiaľkoľvek v okne)</translation>
    </message>
    <message>
        <source>DROP QUEUE
this procedure
finishes (Esc)</source>
        <translation>ZAHODIŤ FRONT
tento postup
dobehne (Esc)</translation>
    </message>
    <message>
        <source>The {0} has no stop command: this button and Esc drop the commands queued after the running one; the procedure it is running finishes</source>
        <translation>{0} nemá príkaz na zastavenie: toto tlačidlo a Esc zahodia príkazy vo fronte za práve vykonávaným; prebiehajúci postup dobehne</translation>
    </message>
    <message>
        <source>DROP QUEUE
this move
finishes (Esc)</source>
        <translation>ZAHODIŤ FRONT
tento pohyb
dobehne (Esc)</translation>
    </message>
    <message>
        <source>The {0} has no stop command: this button and Esc drop the commands queued after the running one; the move it is running finishes</source>
        <translation>{0} nemá príkaz na zastavenie: toto tlačidlo a Esc zahodia príkazy vo fronte za práve vykonávaným; prebiehajúci pohyb dobehne</translation>
    </message>
    <message>
        <source>Stop everything, from anywhere in the window</source>
        <translation>Zastaviť všetko, odkiaľkoľvek v okne</translation>
    </message>
    <message>
        <source>Drop the queued commands, from anywhere (no stop command: this procedure finishes)</source>
        <translation>Zahodiť príkazy vo fronte, odkiaľkoľvek (bez príkazu na zastavenie: tento postup dobehne)</translation>
    </message>
    <message>
        <source>Drop the queued commands, from anywhere (no stop command: this move finishes)</source>
        <translation>Zahodiť príkazy vo fronte, odkiaľkoľvek (bez príkazu na zastavenie: tento pohyb dobehne)</translation>
    </message>
    <message>
        <source>■ Stop</source>
        <translation>■ Zastaviť</translation>
    </message>
    <message>
        <source>■ Drop
queue</source>
        <translation>■ Zahodiť
front</translation>
    </message>
</context>
<context>
    <name>StoredSetting</name>
    <message>
        <source>{0}: {1!r} is not a number</source>
        <extracomment>A whole number. A number with at most ``decimals`` decimals. 0 (off) or 1 (on). A whole number whose bits each mean one thing (``bits`` names them, lowest first). One of ``choices`` (a number that stands for a label). How snapshots and scripts name it: ``&quot;$110&quot;``, ``&quot;X.thread&quot;``. Bit names of a MASK, lowest bit first. A CHOICE&apos;s (value, label) pairs. Why the range is narrower than the device&apos;s own (said with a refusal), or &quot;&quot;. The translation context of the label, description and ``narrowed``. The device keeps the value as a 32-bit float (GRBL): read back, it may differ in its last digits from the one written, and still be the same. The axis a per-axis row is of: its label&apos;s ``{0}``.</extracomment>
        <translation>{0}: {1!r} nie je číslo</translation>
    </message>
    <message>
        <source>{0}: {1} is not a number</source>
        <translation>{0}: {1} nie je číslo</translation>
    </message>
    <message>
        <source>{0}: must be a whole number, not {1}</source>
        <translation>{0}: musí byť celé číslo, nie {1}</translation>
    </message>
    <message>
        <source>{0}: must be within {1}…{2} {3}</source>
        <translation>{0}: musí byť v rozsahu {1}…{2} {3}</translation>
    </message>
    <message>
        <source>{0}: at most {1} decimals are kept, not {2}</source>
        <translation>{0}: uložia sa najviac {1} desatinné miesta, nie {2}</translation>
    </message>
    <message>
        <source>{0}: {1} is none of the choices</source>
        <translation>{0}: {1} nie je žiadna z možností</translation>
    </message>
</context>
<context>
    <name>StoredSettingsPanel</name>
    <message>
        <source>Read</source>
        <extracomment>Keys the operator changed since the device last said what it holds. Keys the last write read back as written (their state says so until the next read). The open &quot;write these differences?&quot; question, while it is asked.</extracomment>
        <translation>Načítať</translation>
    </message>
    <message>
        <source>Read every setting from the device</source>
        <translation>Načítať zo zariadenia všetky nastavenia</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Použiť</translation>
    </message>
    <message>
        <source>Write the edited values, then read them back from the device</source>
        <translation>Zapísať upravené hodnoty a potom ich zo zariadenia prečítať späť</translation>
    </message>
    <message>
        <source>Save snapshot…</source>
        <translation>Uložiť zálohu…</translation>
    </message>
    <message>
        <source>Save every setting to a TOML file</source>
        <translation>Uložiť všetky nastavenia do súboru TOML</translation>
    </message>
    <message>
        <source>Load snapshot…</source>
        <translation>Načítať zálohu…</translation>
    </message>
    <message>
        <source>Show what a snapshot changes, then write only that</source>
        <translation>Ukázať, čo záloha zmení, a zapísať len to</translation>
    </message>
    <message>
        <source>Setting</source>
        <translation>Nastavenie</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Názov</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Hodnota</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Stav</translation>
    </message>
    <message>
        <source>0 (off) or 1 (on)</source>
        <translation>0 (vypnuté) alebo 1 (zapnuté)</translation>
    </message>
    <message>
        <source>Allowed: {0}</source>
        <translation>Povolené: {0}</translation>
    </message>
    <message>
        <source>Bits: {0}</source>
        <translation>Bity: {0}</translation>
    </message>
    <message>
        <source>Not read: {0}</source>
        <translation>Nenačítané: {0}</translation>
    </message>
    <message>
        <source>Reading from the device…</source>
        <translation>Načítavam zo zariadenia…</translation>
    </message>
    <message>
        <source>Nothing changed</source>
        <translation>Nič sa nezmenilo</translation>
    </message>
    <message>
        <source>Not written: {0}</source>
        <translation>Nezapísané: {0}</translation>
    </message>
    <message>
        <source>Writing, then reading back…</source>
        <translation>Zapisujem a potom čítam späť…</translation>
    </message>
    <message>
        <source>Every setting read</source>
        <translation>Všetky nastavenia načítané</translation>
    </message>
    <message>
        <source>Written and read back: {0}</source>
        <translation>Zapísané a prečítané späť: {0}</translation>
    </message>
    <message>
        <source>✗ refused</source>
        <translation>✗ odmietnuté</translation>
    </message>
    <message>
        <source>Save settings snapshot</source>
        <translation>Uložiť zálohu nastavení</translation>
    </message>
    <message>
        <source>Settings snapshots (*.toml)</source>
        <translation>Zálohy nastavení (*.toml)</translation>
    </message>
    <message>
        <source>Load settings snapshot</source>
        <translation>Načítať zálohu nastavení</translation>
    </message>
    <message>
        <source>Not saved: {0} — press Read</source>
        <translation>Neuložené: {0} — stlačte Načítať</translation>
    </message>
    <message>
        <source>Snapshot saved to {0}</source>
        <translation>Záloha uložená do {0}</translation>
    </message>
    <message>
        <source>Not loaded: {0}</source>
        <translation>Nenačítané: {0}</translation>
    </message>
    <message>
        <source>{0}: the device holds every value</source>
        <translation>{0}: zariadenie už drží všetky hodnoty</translation>
    </message>
    <message>
        <source>Values of {0} that differ from the device:</source>
        <translation>Hodnoty z {0}, ktoré sa líšia od zariadenia:</translation>
    </message>
    <message>
        <source>This snapshot was saved on firmware {0}; the device runs {1}. A setting may mean something else there: check each value before writing.</source>
        <translation>Táto záloha bola uložená s firmvérom {0}; zariadenie má {1}. Nastavenie tam môže znamenať niečo iné: pred zápisom skontrolujte každú hodnotu.</translation>
    </message>
    <message>
        <source>This snapshot is of another machine ({0}), not {1}.</source>
        <translation>Táto záloha je z iného stroja ({0}), nie z {1}.</translation>
    </message>
    <message>
        <source>Write anyway</source>
        <translation>Napriek tomu zapísať</translation>
    </message>
    <message>
        <source>Write</source>
        <translation>Zapísať</translation>
    </message>
    <message>
        <source>Writing the snapshot&apos;s values, then reading back…</source>
        <translation>Zapisujem hodnoty zálohy a potom čítam späť…</translation>
    </message>
    <message>
        <source>Snapshot not loaded</source>
        <translation>Záloha nenačítaná</translation>
    </message>
    <message>
        <source>• edited</source>
        <translation>• upravené</translation>
    </message>
    <message>
        <source>✗ not allowed</source>
        <translation>✗ nepovolené</translation>
    </message>
    <message>
        <source>✓ read back</source>
        <translation>✓ prečítané späť</translation>
    </message>
</context>
<context>
    <name>StringArtGeneratorDialog</name>
    <message>
        <source>Photo for string art</source>
        <extracomment>Asks for a photo to open / a folder to export into; None when the operator cancels.</extracomment>
        <translation>Fotografia pre string art</translation>
    </message>
    <message>
        <source>Folder for param.txt and poradi.txt</source>
        <translation>Priečinok pre param.txt a poradi.txt</translation>
    </message>
    <message>
        <source>String art from a photo</source>
        <extracomment>The thread picture was redrawn with this many threads (while generating).</extracomment>
        <translation>String art z fotografie</translation>
    </message>
    <message>
        <source>Photo…</source>
        <extracomment>How far from the centre the winder&apos;s needle goes (its X travel), if known.</extracomment>
        <translation>Fotografia…</translation>
    </message>
    <message>
        <source>Choose a PNG or JPEG photo</source>
        <translation>Vyberte fotografiu PNG alebo JPEG</translation>
    </message>
    <message>
        <source>no photo chosen</source>
        <translation>žiadna fotografia nevybraná</translation>
    </message>
    <message>
        <source>The photo cropped to the board</source>
        <translation>Fotografia orezaná na dosku</translation>
    </message>
    <message>
        <source>The thread, as wound at the real width</source>
        <translation>Niť, ako bude navinutá v skutočnej šírke</translation>
    </message>
    <message>
        <source>Photo on the board</source>
        <translation>Fotografia na doske</translation>
    </message>
    <message>
        <source>Thread</source>
        <translation>Niť</translation>
    </message>
    <message>
        <source>Choose a photo</source>
        <translation>Vyberte fotografiu</translation>
    </message>
    <message>
        <source>Generate</source>
        <translation>Vytvoriť</translation>
    </message>
    <message>
        <source>Make the nail sequence</source>
        <translation>Vytvoriť poradie klincov</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Zrušiť</translation>
    </message>
    <message>
        <source>Stop; nothing is kept</source>
        <translation>Zastaviť; nič sa neuchová</translation>
    </message>
    <message>
        <source>Export…</source>
        <translation>Exportovať…</translation>
    </message>
    <message>
        <source>Write param.txt, poradi.txt and a PNG into a folder</source>
        <translation>Zapísať param.txt, poradi.txt a PNG do priečinka</translation>
    </message>
    <message>
        <source>Load as job</source>
        <translation>Načítať ako úlohu</translation>
    </message>
    <message>
        <source>Open the sequence in the jobs dock to drill and wind it</source>
        <translation>Otvoriť poradie v paneli úloh na vŕtanie a navíjanie</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Zavrieť</translation>
    </message>
    <message>
        <source>Close (a generation is cancelled)</source>
        <translation>Zavrieť (prebiehajúci výpočet sa zruší)</translation>
    </message>
    <message>
        <source>circle</source>
        <translation>kruh</translation>
    </message>
    <message>
        <source>{0}-gon</source>
        <translation>{0}-uholník</translation>
    </message>
    <message>
        <source>Board radius (polomer_matrice); the nails sit 1.5 cm inside</source>
        <translation>Polomer dosky (polomer_matrice); klince sú 1,5 cm od okraja</translation>
    </message>
    <message>
        <source>The line budget</source>
        <translation>Počet čiar k dispozícii</translation>
    </message>
    <message>
        <source>The real thread&apos;s width: it sets how dark each thread looks</source>
        <translation>Skutočná šírka nite: určuje, ako tmavo každá niť vyzerá</translation>
    </message>
    <message>
        <source>Least nails between a thread&apos;s two ends (never to a neighbouring nail)</source>
        <translation>Najmenší počet klincov medzi koncami nite (nikdy na susedný klinec)</translation>
    </message>
    <message>
        <source>Pixels across the nail circle</source>
        <translation>Pixelov cez kružnicu klincov</translation>
    </message>
    <message>
        <source>Shape</source>
        <translation>Tvar</translation>
    </message>
    <message>
        <source>Nails</source>
        <translation>Klince</translation>
    </message>
    <message>
        <source>Board radius</source>
        <translation>Polomer dosky</translation>
    </message>
    <message>
        <source>Line budget</source>
        <translation>Počet čiar</translation>
    </message>
    <message>
        <source>Thread width</source>
        <translation>Šírka nite</translation>
    </message>
    <message>
        <source>Minimum skip</source>
        <translation>Najmenší preskok</translation>
    </message>
    <message>
        <source>Raster</source>
        <translation>Raster</translation>
    </message>
    <message>
        <source>Crop: 1 fits the photo&apos;s shorter side to the board</source>
        <translation>Orez: 1 prispôsobí kratšiu stranu fotografie doske</translation>
    </message>
    <message>
        <source>Invert (light thread, dark board)</source>
        <translation>Invertovať (svetlá niť, tmavá doska)</translation>
    </message>
    <message>
        <source>Zoom</source>
        <translation>Zväčšenie</translation>
    </message>
    <message>
        <source>Centre across</source>
        <translation>Stred vodorovne</translation>
    </message>
    <message>
        <source>Centre down</source>
        <translation>Stred zvisle</translation>
    </message>
    <message>
        <source>Contrast</source>
        <translation>Kontrast</translation>
    </message>
    <message>
        <source>Brightness</source>
        <translation>Jas</translation>
    </message>
    <message>
        <source>reading &lt;b&gt;{0}&lt;/b&gt;…</source>
        <translation>načítavam &lt;b&gt;{0}&lt;/b&gt;…</translation>
    </message>
    <message>
        <source>Set the board and the crop, then Generate</source>
        <translation>Nastavte dosku a orez, potom Vytvoriť</translation>
    </message>
    <message>
        <source>Not opened: {0}</source>
        <translation>Neotvorené: {0}</translation>
    </message>
    <message>
        <source>Both pictures: the nail circle, {0} cm across, drawn {1} px wide (1 px = {2} mm).
Thread {3} mm = 1/{4} of it; chosen on a raster of {5} mm pixels.</source>
        <translation>Oba obrázky: kružnica klincov s priemerom {0} cm vykreslená na šírku {1} px (1 px = {2} mm).
Niť {3} mm = 1/{4} priemeru; volené na rastri s pixelmi {5} mm.</translation>
    </message>
    <message>
        <source>Cannot generate: {0}</source>
        <translation>Nedá sa vytvoriť: {0}</translation>
    </message>
    <message>
        <source>This winder&apos;s needle reaches {0} mm from the centre: boards up to {1} cm radius fit it (export the files for a larger one).</source>
        <translation>Ihla tejto navíjačky dosiahne {0} mm od stredu: zmestia sa dosky do polomeru {1} cm (pre väčšie súbory exportujte).</translation>
    </message>
    <message>
        <source>Preparing the lines between the nails…</source>
        <translation>Pripravujem čiary medzi klincami…</translation>
    </message>
    <message>
        <source>Cancelling…</source>
        <translation>Ruším…</translation>
    </message>
    <message>
        <source>Preparing the lines between the nails: {0} of {1}</source>
        <translation>Pripravujem čiary medzi klincami: {0} z {1}</translation>
    </message>
    <message>
        <source>Winding: {0} threads of at most {1}</source>
        <translation>Navíjanie: {0} nití z najviac {1}</translation>
    </message>
    <message>
        <source>stopped before the budget: no further thread brings it closer</source>
        <translation>zastavené pred vyčerpaním: žiadna ďalšia niť obraz nezlepší</translation>
    </message>
    <message>
        <source>the whole budget</source>
        <translation>celý počet</translation>
    </message>
    <message numerus="yes">
        <source>%n thread(s) ({0}), {1} m of thread; {2}; {3} s</source>
        <translation>
            <numerusform>%n niť ({0}), {1} m nite; {2}; {3} s</numerusform>
            <numerusform>%n nite ({0}), {1} m nite; {2}; {3} s</numerusform>
            <numerusform>%n nití ({0}), {1} m nite; {2}; {3} s</numerusform>
        </translation>
    </message>
    <message>
        <source>Cancelled: nothing kept</source>
        <translation>Zrušené: nič neuchované</translation>
    </message>
    <message>
        <source>Generation failed: {0}</source>
        <translation>Výpočet zlyhal: {0}</translation>
    </message>
    <message>
        <source>Nothing written to {0}: {1}</source>
        <translation>Do {0} nič nezapísané: {1}</translation>
    </message>
    <message>
        <source>Wrote {0} in {1}</source>
        <translation>Zapísané {0} do {1}</translation>
    </message>
    <message>
        <source>Not loaded: nothing written to {0}: {1}</source>
        <translation>Nenačítané: do {0} nič nezapísané: {1}</translation>
    </message>
    <message>
        <source>Not loaded: see the jobs dock&apos;s messages</source>
        <translation>Nenačítané: pozri správy v paneli úloh</translation>
    </message>
</context>
<context>
    <name>Supervision</name>
    <message>
        <source>outside the travel</source>
        <translation>mimo dráhy pojazdu</translation>
    </message>
    <message>
        <source>past the target</source>
        <translation>za cieľom</translation>
    </message>
    <message>
        <source>moved while nothing was sent</source>
        <translation>pohol sa, hoci nič nebolo odoslané</translation>
    </message>
    <message>
        <source>off the path of the moves sent</source>
        <translation>mimo dráhy odoslaných pohybov</translation>
    </message>
    <message>
        <source>no move</source>
        <translation>žiadny pohyb</translation>
    </message>
    <message>
        <source>Machine stopped: it reported {0}, {1} ({2}); expected {3}, {4} mm away</source>
        <translation>Stroj zastavený: hlásil {0}, {1} ({2}); očakávané {3}, vzdialenosť {4} mm</translation>
    </message>
</context>
<context>
    <name>TelemetryDock</name>
    <message>
        <source>Telemetry</source>
        <translation>Telemetria</translation>
    </message>
    <message>
        <source>Variable</source>
        <translation>Premenná</translation>
    </message>
    <message>
        <source>Subscriber variable to plot; the station asks for it in every frame the info panel does not need</source>
        <translation>Premenná odberateľa na vykreslenie; stanica si ju vyžiada v každom rámci, ktorý nepotrebuje informačný panel</translation>
    </message>
    <message>
        <source>none</source>
        <translation>žiadna</translation>
    </message>
    <message>
        <source>Window</source>
        <translation>Okno</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pozastaviť</translation>
    </message>
    <message>
        <source>Freeze the plots; recording goes on</source>
        <translation>Zmraziť grafy; záznam pokračuje</translation>
    </message>
    <message>
        <source>Autoscale</source>
        <translation>Automatická mierka</translation>
    </message>
    <message>
        <source>Fit each plot&apos;s vertical range to what is shown (dragging a plot turns it off)</source>
        <translation>Prispôsobiť zvislý rozsah každého grafu zobrazeným dátam (ťahanie grafu to vypne)</translation>
    </message>
    <message>
        <source>Export CSV…</source>
        <translation>Exportovať CSV…</translation>
    </message>
    <message>
        <source>Save the samples shown, with units, as CSV</source>
        <translation>Uložiť zobrazené vzorky s jednotkami ako CSV</translation>
    </message>
    <message>
        <source>Export PNG…</source>
        <translation>Exportovať PNG…</translation>
    </message>
    <message>
        <source>Save the plots as an image</source>
        <translation>Uložiť grafy ako obrázok</translation>
    </message>
    <message>
        <source>paused — recording goes on</source>
        <translation>pozastavené — záznam pokračuje</translation>
    </message>
    <message>
        <source>position</source>
        <translation>poloha</translation>
    </message>
    <message>
        <source>velocity</source>
        <translation>rýchlosť</translation>
    </message>
    <message>
        <source>time before the pause</source>
        <translation>čas pred pozastavením</translation>
    </message>
    <message>
        <source>time before now</source>
        <translation>čas pred okamihom</translation>
    </message>
    <message>
        <source>Rotation</source>
        <translation>Natočenie</translation>
    </message>
    <message>
        <source>Zero</source>
        <translation>Vynulovať</translation>
    </message>
    <message>
        <source>Make the present angle read 0°</source>
        <translation>Nastaviť súčasný uhol na 0°</translation>
    </message>
    <message>
        <source>Paused</source>
        <translation>Pozastavené</translation>
    </message>
    <message>
        <source>Export telemetry as CSV</source>
        <translation>Exportovať telemetriu ako CSV</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>Súbory CSV (*.csv)</translation>
    </message>
    <message>
        <source>Export telemetry plots as PNG</source>
        <translation>Exportovať grafy telemetrie ako PNG</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>Obrázky PNG (*.png)</translation>
    </message>
    <message>
        <source>variable (none)</source>
        <translation>premenná (žiadna)</translation>
    </message>
    <message>
        <source>This machine reports no subscriber variables</source>
        <translation>Tento stroj nehlási žiadne premenné odberateľa</translation>
    </message>
</context>
<context>
    <name>Unit</name>
    <message>
        <source>deg</source>
        <extracomment>The unit words the station shows, for lupdate; anything else is a symbol.</extracomment>
        <translation>°</translation>
    </message>
    <message>
        <source>deg/s</source>
        <translation>°/s</translation>
    </message>
    <message>
        <source>steps</source>
        <translation>krokov</translation>
    </message>
    <message>
        <source>µsteps</source>
        <translation>µkrokov</translation>
    </message>
    <message>
        <source>mm/rev</source>
        <translation>mm/ot</translation>
    </message>
    <message>
        <source>frames</source>
        <translation>rámcov</translation>
    </message>
    <message>
        <source>step/mm</source>
        <extracomment>The unit words of the stored settings, for lupdate (symbols like mm pass unchanged; the window&apos;s :mod:`widgets.units` says the others in the same context).</extracomment>
        <translation>krokov/mm</translation>
    </message>
    <message>
        <source>RPM</source>
        <translation>ot/min</translation>
    </message>
</context>
<context>
    <name>Usb3Panel</name>
    <message>
        <source>Move by</source>
        <translation>Posunúť o</translation>
    </message>
    <message>
        <source>Will move</source>
        <translation>Skutočne prejde</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Krok</translation>
    </message>
    <message>
        <source>Thread</source>
        <translation>Niť</translation>
    </message>
    <message>
        <source>Signed distance to move {0} (fractions allowed)</source>
        <translation>Vzdialenosť so znamienkom na posun {0} (aj desatinná)</translation>
    </message>
    <message>
        <source>The unit moves in whole steps: this is what it will really move</source>
        <translation>Jednotka sa pohybuje po celých krokoch: toľko skutočne prejde</translation>
    </message>
    <message>
        <source>full</source>
        <comment>full step</comment>
        <translation>celý</translation>
    </message>
    <message>
        <source>Send {0}</source>
        <translation>Odoslať {0}</translation>
    </message>
    <message>
        <source>{0} distance</source>
        <translation>Vzdialenosť {0}</translation>
    </message>
    <message>
        <source>Zero all</source>
        <translation>Vynulovať všetko</translation>
    </message>
    <message>
        <source>Set every axis&apos; position to 0 where it stands (C;)</source>
        <translation>Nastaviť polohu všetkých osí tam, kde stoja, na 0 (C;)</translation>
    </message>
    <message>
        <source>Send all</source>
        <translation>Odoslať všetko</translation>
    </message>
    <message>
        <source>Move every axis by its distance, all starting together</source>
        <translation>Posunie každú os o jej vzdialenosť, všetky sa rozbehnú naraz</translation>
    </message>
    <message>
        <source>The unit moves in whole steps; top speed at this step size {0} mm/s</source>
        <translation>Jednotka sa pohybuje po celých krokoch; najvyššia rýchlosť pri tomto kroku {0} mm/s</translation>
    </message>
</context>
<context>
    <name>Usb3Session</name>
    <message>
        <source>{0}: {1} mm is less than one step</source>
        <extracomment>How far ahead of the key a jog keeps the axis, in seconds of travel at top rate. Seconds without any reply before the unit is asked ``G;``, then late (amber), then lost. ``C;`` was sent and the axis has not reported since: its next report is a new zero. Asked where it stands (a move of nothing) and not answered yet: its next report is where it stands, not a motion. Axes asked where they stand at rest, which must stand (a question run as a move). Where the jog leads sent so far take each axis (None: from its position). Per axis: the count the moves sent are heading for, their direction and when the last was sent (None: no move of the station&apos;s under way). Per axis: the count it stood at when a move was sent to it at rest (None: none). Station-clock time of the unit&apos;s last ``?;`` (None: none on this link). The direction register as the station last set it (``D``). Station-clock time of each axis&apos;s last position report. Per axis, the path (in counts) of the moves sent that the reports must follow. After a silence: per axis, the counts the unit may stand at (from where it was to where the moves sent take it), and whether it has been asked where it stands. Each axis&apos;s count when the silence began (what it answers if nothing sent meanwhile ran). Which settings reports came since the link opened (the first always counts).</extracomment>
        <translation>{0}: {1} mm je menej ako jeden krok</translation>
    </message>
    <message>
        <source>Nothing to move: every distance is less than one step</source>
        <translation>Nie je čím pohnúť: každá vzdialenosť je menšia ako jeden krok</translation>
    </message>
    <message>
        <source>This unit has no stop command: it finishes its move</source>
        <translation>Táto jednotka nemá príkaz zastavenia: dokončí svoj pohyb</translation>
    </message>
    <message>
        <source>{0} {1} mm, {2} counts</source>
        <extracomment>An axis that has not reported for this long after a report has stopped. An axis stopped at an end switch: axis index, &quot;low&quot; or &quot;high&quot;, position in mm. The unit answered ``?;`` and an axis never left where its move began: the move was the command it could not read. Axis index, position in mm.</extracomment>
        <translation>{0} {1} mm, {2} dielikov</translation>
    </message>
    <message>
        <source>{0} asked where it stands, a move of nothing</source>
        <translation>{0}: otázka, kde stojí (pohyb o nič)</translation>
    </message>
    <message>
        <source>{0} stopped at its high end switch at {1} mm, {2} mm short of its target</source>
        <translation>{0} sa zastavila na hornom koncovom spínači na {1} mm, {2} mm pred cieľom</translation>
    </message>
    <message>
        <source>{0} stopped at its low end switch at {1} mm, {2} mm short of its target</source>
        <translation>{0} sa zastavila na dolnom koncovom spínači na {1} mm, {2} mm pred cieľom</translation>
    </message>
    <message>
        <source>The unit could not read the move of {0} (it answered ?;) and did not move it: {0} stands at {1} mm</source>
        <translation>Jednotka neprečítala pohyb {0} (odpovedala ?;) a nepohla ňou: {0} stojí na {1} mm</translation>
    </message>
    <message>
        <source>Garbage from the unit dropped: {0}</source>
        <translation>Nezmyselné dáta z jednotky zahodené: {0}</translation>
    </message>
    <message>
        <source>The unit did not understand a command (?;)</source>
        <translation>Jednotka nerozumela príkazu (?;)</translation>
    </message>
</context>
<context>
    <name>Usb3Setting</name>
    <message>
        <source>full step</source>
        <translation>celý krok</translation>
    </message>
    <message>
        <source>1/2 step</source>
        <translation>1/2 kroku</translation>
    </message>
    <message>
        <source>1/4 step</source>
        <translation>1/4 kroku</translation>
    </message>
    <message>
        <source>1/8 step</source>
        <translation>1/8 kroku</translation>
    </message>
    <message>
        <source>1/16 step</source>
        <translation>1/16 kroku</translation>
    </message>
    <message>
        <source>1/32 step</source>
        <translation>1/32 kroku</translation>
    </message>
    <message>
        <source>{0} step size</source>
        <translation>{0} veľkosť kroku</translation>
    </message>
    <message>
        <source>The driver&apos;s microstep: finer steps move more smoothly and more slowly (the pulse rate stays the same).</source>
        <translation>Mikrokrok budiča: jemnejšie kroky idú plynulejšie a pomalšie (frekvencia impulzov zostáva rovnaká).</translation>
    </message>
    <message>
        <source>{0} thread</source>
        <translation>{0} závit</translation>
    </message>
    <message>
        <source>The axis&apos;s lead screw: how far one turn moves it. It decides how the unit&apos;s counts become millimetres.</source>
        <translation>Pohybová skrutka osi: ako ďaleko ju posunie jedna otáčka. Určuje, ako sa počty jednotky prevádzajú na milimetre.</translation>
    </message>
</context>
<context>
    <name>WorkZero</name>
    <message>
        <source>no axis to zero</source>
        <extracomment>GRBL 1.1&apos;s work coordinate systems (``N_COORDINATE_SYSTEM``). The firmware has GRBL&apos;s work systems (the registry says; False until it does). The system in use as far as known (None before the board&apos;s first reset or $G). Each system&apos;s stored offset, as the board&apos;s last ``$#`` listed it.</extracomment>
        <translation>žiadna os na vynulovanie</translation>
    </message>
    <message>
        <source>{0} is none of G54…G59</source>
        <translation>{0} nie je žiadny z G54…G59</translation>
    </message>
    <message>
        <source>not sent: the board has not reported its work offset yet</source>
        <translation>neodoslané: doska ešte nenahlásila svoj pracovný posun</translation>
    </message>
    <message>
        <source>this machine&apos;s firmware has no work coordinate systems</source>
        <translation>firmvér tohto stroja nemá pracovné súradnicové systémy</translation>
    </message>
    <message>
        <source>Work zero: {0}</source>
        <translation>Pracovná nula: {0}</translation>
    </message>
</context>
<context>
    <name>WorkZeroBox</name>
    <message>
        <source>Work zero</source>
        <translation>Pracovná nula</translation>
    </message>
    <message>
        <source>The coordinate system in use and its offset from the machine zero</source>
        <translation>Používaný súradnicový systém a jeho posun od nuly stroja</translation>
    </message>
    <message>
        <source>Zero {0}</source>
        <translation>Nula {0}</translation>
    </message>
    <message>
        <source>Here is {0} 0 in the system in use (G10 L20 P0 {0}0); nothing moves</source>
        <translation>Tu je {0} 0 v používanom systéme (G10 L20 P0 {0}0); nič sa nepohne</translation>
    </message>
    <message>
        <source>Zero all</source>
        <translation>Vynulovať všetko</translation>
    </message>
    <message>
        <source>Here is the work zero of every axis (G10 L20 P0); nothing moves</source>
        <translation>Tu je pracovná nula všetkých osí (G10 L20 P0); nič sa nepohne</translation>
    </message>
    <message>
        <source>Go to work zero</source>
        <translation>Na pracovnú nulu</translation>
    </message>
    <message>
        <source>Lift the pen, then travel to the work zero (G90 G0)</source>
        <translation>Zdvihnúť pero a prejsť na pracovnú nulu (G90 G0)</translation>
    </message>
    <message>
        <source>Read</source>
        <translation>Načítať</translation>
    </message>
    <message>
        <source>Ask the board for its systems ($G, $#)</source>
        <translation>Opýtať sa dosky na jej systémy ($G, $#)</translation>
    </message>
    <message>
        <source>Work in {0} from now on (its own zero); nothing moves</source>
        <translation>Odteraz pracovať v {0} (jeho vlastná nula); nič sa nepohne</translation>
    </message>
    <message>
        <source>In use</source>
        <translation>Používa sa</translation>
    </message>
</context>
</TS>

<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="cs">
<context>
    <name>AbsolutePanel</name>
    <message>
        <source>Move to</source>
        <translation>Najet na</translation>
    </message>
    <message>
        <source>{0} target, 0…{1} {2} (Esc stops)</source>
        <translation>Cílová poloha {0}, 0…{1} {2} (Esc zastaví)</translation>
    </message>
    <message>
        <source>Go {0}</source>
        <translation>Jet {0}</translation>
    </message>
    <message>
        <source>Move {0} to the target</source>
        <translation>Najet osou {0} na cílovou polohu</translation>
    </message>
    <message>
        <source>{0} target</source>
        <translation>Cíl {0}</translation>
    </message>
    <message>
        <source>Go all</source>
        <translation>Jet se všemi</translation>
    </message>
    <message>
        <source>Move every axis to its target at once</source>
        <translation>Najet všemi osami naráz na jejich cílové polohy</translation>
    </message>
</context>
<context>
    <name>AxisStatus</name>
    <message>
        <source>unknown</source>
        <extracomment>Every axis status a session reports (the stage&apos;s, the drill&apos;s, usb3&apos;s and GRBL&apos;s).</extracomment>
        <translation>neznámý</translation>
    </message>
    <message>
        <source>idle</source>
        <translation>v klidu</translation>
    </message>
    <message>
        <source>moving</source>
        <translation>v pohybu</translation>
    </message>
    <message>
        <source>parking</source>
        <translation>parkuje</translation>
    </message>
    <message>
        <source>parked</source>
        <translation>zaparkováno</translation>
    </message>
    <message>
        <source>accelerating</source>
        <translation>zrychluje</translation>
    </message>
    <message>
        <source>constant speed</source>
        <translation>konstantní rychlost</translation>
    </message>
    <message>
        <source>decelerating</source>
        <translation>brzdí</translation>
    </message>
    <message>
        <source>target reached</source>
        <translation>v cíli</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>zastaveno</translation>
    </message>
    <message>
        <source>homing</source>
        <translation>referenční jízda</translation>
    </message>
    <message>
        <source>end switch hit</source>
        <translation>narazil na koncový spínač</translation>
    </message>
    <message>
        <source>blocked: battery low</source>
        <translation>blokováno: slabá baterie</translation>
    </message>
    <message>
        <source>blocked: charger connected</source>
        <translation>blokováno: připojena nabíječka</translation>
    </message>
    <message>
        <source>blocked: USB connected</source>
        <translation>blokováno: připojeno USB</translation>
    </message>
    <message>
        <source>sleeping</source>
        <translation>spí</translation>
    </message>
    <message>
        <source>driver fault</source>
        <translation>porucha budiče</translation>
    </message>
    <message>
        <source>parameter rejected</source>
        <translation>parametr odmítnut</translation>
    </message>
    <message>
        <source>unknown command</source>
        <translation>neznámý příkaz</translation>
    </message>
    <message>
        <source>run</source>
        <translation>běží</translation>
    </message>
    <message>
        <source>hold</source>
        <translation>pozastaveno</translation>
    </message>
    <message>
        <source>jog</source>
        <translation>ruční posuv</translation>
    </message>
    <message>
        <source>alarm</source>
        <translation>alarm</translation>
    </message>
    <message>
        <source>door</source>
        <translation>dvířka otevřena</translation>
    </message>
    <message>
        <source>check</source>
        <translation>kontrolní režim</translation>
    </message>
    <message>
        <source>home</source>
        <translation>referenční jízda</translation>
    </message>
    <message>
        <source>sleep</source>
        <translation>spánek</translation>
    </message>
</context>
<context>
    <name>BoardDialog</name>
    <message>
        <source>String-art board</source>
        <translation>Deska pro string art</translation>
    </message>
    <message numerus="yes">
        <source>&lt;b&gt;{0}&lt;/b&gt; lists %n nail visit(s) without a param.txt. Which board is it for?</source>
        <translation>
            <numerusform>&lt;b&gt;{0}&lt;/b&gt; obsahuje %n návštěvu hřebíku bez souboru param.txt. Pro jakou desku je?</numerusform>
            <numerusform>&lt;b&gt;{0}&lt;/b&gt; obsahuje %n návštěvy hřebíků bez souboru param.txt. Pro jakou desku je?</numerusform>
            <numerusform>&lt;b&gt;{0}&lt;/b&gt; obsahuje %n návštěv hřebíků bez souboru param.txt. Pro jakou desku je?</numerusform>
        </translation>
    </message>
    <message>
        <source>circle</source>
        <translation>kruh</translation>
    </message>
    <message>
        <source>{0}-gon</source>
        <translation>{0}úhelník</translation>
    </message>
    <message>
        <source>At least {0}: the list names nail {1}</source>
        <translation>Nejméně {0}: seznam uvádí hřebík {1}</translation>
    </message>
    <message>
        <source>Board radius; the nails sit 1.5 cm inside its edge</source>
        <translation>Poloměr desky; hřebíky jsou 1,5 cm od jejího okraje</translation>
    </message>
    <message>
        <source>Shape</source>
        <translation>Tvar</translation>
    </message>
    <message>
        <source>Nails</source>
        <translation>Hřebíky</translation>
    </message>
    <message>
        <source>Board radius</source>
        <translation>Poloměr desky</translation>
    </message>
</context>
<context>
    <name>ConnectionPanel</name>
    <message>
        <source>Built-in emulator</source>
        <translation>Vestavěný emulátor</translation>
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
        <translation>Přepnutím stroje se toto spojení ukončí a otevře se nové</translation>
    </message>
    <message>
        <source>Refresh</source>
        <translation>Obnovit</translation>
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
        <translation>Přenosová rychlost</translation>
    </message>
    <message>
        <source>Scan</source>
        <translation>Hledat</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>Připojit</translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation>Odpojit</translation>
    </message>
    <message>
        <source>Stop every axis, wait briefly for the machine to confirm, then close the link</source>
        <translation>Zastaví všechny osy, krátce počká na potvrzení stroje a pak ukončí spojení</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Stroj</translation>
    </message>
    <message>
        <source>Link</source>
        <translation>Spojení</translation>
    </message>
    <message>
        <source>(no name)</source>
        <translation>(bez názvu)</translation>
    </message>
    <message>
        <source>Scanning…</source>
        <translation>Hledám…</translation>
    </message>
    <message numerus="yes">
        <source>%n found</source>
        <translation>
            <numerusform>nalezeno %n zařízení</numerusform>
            <numerusform>nalezena %n zařízení</numerusform>
            <numerusform>nalezeno %n zařízení</numerusform>
        </translation>
    </message>
    <message>
        <source>No stage found</source>
        <translation>Žádný stolek nenalezen</translation>
    </message>
    <message>
        <source>Choose a serial port first (Refresh lists them).</source>
        <translation>Nejdřív vyberte sériový port (Obnovit je vypíše).</translation>
    </message>
</context>
<context>
    <name>ConsoleGate</name>
    <message>
        <source>{0} would move {1}</source>
        <extracomment>GRBL&apos;s &quot;setting disabled&quot;: for ``$H`` it means homing is off (``$22=0``, a new board&apos;s). Whether the board is in G91 after the lines queued (a reset brings back G90).</extracomment>
        <translation>{0} by pohnul {1}</translation>
    </message>
    <message>
        <source>. Homing is switched off on the board ($22=0, GRBL&apos;s default): with end switches fitted, send $22=1 from the console; without them, move the machine to its origin by hand and set it there</source>
        <translation>. Referenční jízda je na desce vypnutá ($22=0, výchozí v GRBL): s koncovými spínači pošlete z konzole $22=1; bez nich přesuňte stroj do počátku ručně a nastavte ho tam</translation>
    </message>
</context>
<context>
    <name>DeveloperPane</name>
    <message>
        <source>Developer</source>
        <translation>Vývojář</translation>
    </message>
    <message>
        <source>Simulation: the built-in emulator answers the commands</source>
        <translation>Simulace: na příkazy odpovídá vestavěný emulátor</translation>
    </message>
    <message>
        <source>On: connect the emulated stage (when no device is connected). Off: disconnect it.</source>
        <translation>Zapnuto: připojí emulovaný stolek (není-li připojeno žádné zařízení). Vypnuto: odpojí ho.</translation>
    </message>
    <message>
        <source>Simulation refused: {0}</source>
        <translation>Simulace odmítnuta: {0}</translation>
    </message>
</context>
<context>
    <name>DrillConversionBox</name>
    <message>
        <source>Conversion constants (teaching)</source>
        <translation>Převodní konstanty (výuka)</translation>
    </message>
    <message>
        <source>Excellon step, 1/… inch</source>
        <translation>Krok Excellon, 1/… palce</translation>
    </message>
    <message>
        <source>Excellon step</source>
        <translation>Krok Excellon</translation>
    </message>
    <message>
        <source>Excellon step 1/… inch</source>
        <translation>Krok Excellon 1/… palce</translation>
    </message>
    <message>
        <source>{0} microsteps a mm</source>
        <translation>{0} mikrokroků na mm</translation>
    </message>
    <message>
        <source>Teaching only: with other values than the profile&apos;s the drill goes where these send it, not where the file means (the travel is still checked).</source>
        <translation>Jen pro výuku: s jinými hodnotami než v profilu jede vrtačka tam, kam ji pošlou tyto, ne kam míní soubor (rozsah pojezdu se stále kontroluje).</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Použít</translation>
    </message>
    <message>
        <source>Read the loaded job again with these constants</source>
        <translation>Načíst úlohu znovu s těmito konstantami</translation>
    </message>
    <message>
        <source>Profile values</source>
        <translation>Hodnoty profilu</translation>
    </message>
    <message>
        <source>Back to the machine profile&apos;s constants</source>
        <translation>Zpět na konstanty profilu stroje</translation>
    </message>
    <message>
        <source>Not changed: {0}</source>
        <translation>Nezměněno: {0}</translation>
    </message>
</context>
<context>
    <name>DrillDriver</name>
    <message>
        <source>The hole at {0} may or may not have been drilled: the link went before the drill confirmed the command. Look at the board (the hole is marked in the preview), then drill it again or count it as drilled.</source>
        <translation>Otvor na {0} možná je, možná není vyvrtaný: spojení spadlo dřív, než vrtačka příkaz potvrdila. Podívejte se na desku (otvor je vyznačen v náhledu) a pak ho vyvrtejte znovu, nebo ho započítejte jako vyvrtaný.</translation>
    </message>
    <message>
        <source>Drill it again</source>
        <translation>Vyvrtat znovu</translation>
    </message>
    <message>
        <source>Count it as drilled</source>
        <translation>Započítat jako vyvrtaný</translation>
    </message>
    <message>
        <source>the drill ran a command the station did not send ({0}): a hole may have been drilled twice or in the wrong place; look at the board</source>
        <translation>vrtačka provedla příkaz, který stanice neposlala ({0}): díra mohla být vyvrtána dvakrát nebo na špatném místě; zkontrolujte desku</translation>
    </message>
</context>
<context>
    <name>DrillPanel</name>
    <message>
        <source>N  home</source>
        <extracomment>A move expected to run longer than this (seconds) asks first: it cannot be stopped. Buttons of the procedures that take no value: letter, caption, tooltip.</extracomment>
        <translation>N  reference</translation>
    </message>
    <message>
        <source>Home X then Y to the switches and the zero offsets</source>
        <translation>Referenční jízda X, pak Y na spínače a nulové posuny</translation>
    </message>
    <message>
        <source>V  drill</source>
        <translation>V  vrtat</translation>
    </message>
    <message>
        <source>Drill one hole where the head stands</source>
        <translation>Vyvrtat jeden otvor tam, kde stojí hlava</translation>
    </message>
    <message>
        <source>K  pen down</source>
        <translation>K  pero dolů</translation>
    </message>
    <message>
        <source>Lower the pen</source>
        <translation>Spustit pero</translation>
    </message>
    <message>
        <source>Z  pen up</source>
        <translation>Z  pero nahoru</translation>
    </message>
    <message>
        <source>Raise the pen</source>
        <translation>Zvednout pero</translation>
    </message>
    <message>
        <source>P  park</source>
        <translation>P  parkovat</translation>
    </message>
    <message>
        <source>Park at the back and switch the motors off</source>
        <translation>Zaparkovat vzadu a vypnout motory</translation>
    </message>
    <message>
        <source>Commands</source>
        <translation>Příkazy</translation>
    </message>
    <message>
        <source>Timing…</source>
        <translation>Časování…</translation>
    </message>
    <message>
        <source>Show the drill&apos;s timing constants, to change them</source>
        <translation>Ukázat časovací konstanty vrtačky a změnit je</translation>
    </message>
    <message>
        <source>Step through…</source>
        <translation>Krokování…</translation>
    </message>
    <message>
        <source>Walk the loaded job line by line and send its procedures by hand</source>
        <translation>Projít načtenou úlohu řádek po řádku a posílat její procedury ručně</translation>
    </message>
    <message>
        <source>Constants…</source>
        <translation>Konstanty…</translation>
    </message>
    <message>
        <source>Show the Excellon step and microsteps a mm, to change them</source>
        <translation>Ukázat krok Excellon a mikrokroky na mm, ke změně</translation>
    </message>
    <message>
        <source>Move to (microsteps from zero)</source>
        <translation>Najet na (mikrokroky od nuly)</translation>
    </message>
    <message>
        <source>{0} target; {1} microsteps a mm</source>
        <translation>Cíl {0}; {1} mikrokroků na mm</translation>
    </message>
    <message>
        <source>Send {0}</source>
        <translation>Odeslat {0}</translation>
    </message>
    <message>
        <source>{0} target</source>
        <translation>Cíl {0}</translation>
    </message>
    <message>
        <source>Send anyway</source>
        <translation>Přesto odeslat</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Zrušit</translation>
    </message>
    <message>
        <source>Terminal</source>
        <translation>Terminál</translation>
    </message>
    <message>
        <source>Send</source>
        <translation>Odeslat</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Vymazat</translation>
    </message>
    <message>
        <source>Clear the terminal and the columns</source>
        <translation>Vymazat terminál a sloupce</translation>
    </message>
    <message>
        <source>command received</source>
        <translation>příkaz přijat</translation>
    </message>
    <message>
        <source>command done</source>
        <translation>příkaz proveden</translation>
    </message>
    <message>
        <source>! {0}: not sent</source>
        <translation>! {0}: neodesláno</translation>
    </message>
    <message>
        <source>&lt;b&gt;{0}&lt;/b&gt; runs about {1} s, and the drill has no stop command: once it starts, STOP and Esc only drop what is queued after it. Send it?</source>
        <translation>&lt;b&gt;{0}&lt;/b&gt; poběží asi {1} s a vrtačka nemá příkaz k zastavení: jakmile se rozjede, STOP a Esc jen zahodí, co je ve frontě za ním. Odeslat?</translation>
    </message>
    <message>
        <source>   (link check: is the drill there?)</source>
        <extracomment>The device acknowledged the command in flight (``R``); the command&apos;s text. The command in flight has finished (``D``); the command&apos;s text. The device refused the command in flight (``E``); the queue was cleared. The last queued command is done and nothing is waiting. The drill acknowledged or finished what the station did not send, in a way that can harm (a drill cycle run twice, another procedure): the message says what was heard. A line for the terminal: ``&gt; X248`` as sent, ``&lt; RX`` as heard (the text decoded here, so the page only shows it). Station-clock time by which the device must have answered the command in flight. Since when the reply due has been awaited, and from when on it is late. Probes (``I``) written and not yet answered ``EI``. After a silence: until when the drill may still be running the command it had.</extracomment>
        <translation>   (kontrola spojení: je vrtačka připojena?)</translation>
    </message>
    <message>
        <source>  (link check answered: the drill is there)</source>
        <translation>  (kontrola spojení zodpovězena: vrtačka je připojena)</translation>
    </message>
    <message>
        <source>! {0} refused by the drill; queue cleared</source>
        <translation>! {0} vrtačka odmítla; fronta vyprázdněna</translation>
    </message>
</context>
<context>
    <name>DrillSession</name>
    <message>
        <source>The drill has no stop command: {0} queued command(s) dropped; {1} finishes its procedure</source>
        <translation>Vrtačka nemá příkaz k zastavení: zahozeno příkazů ve frontě: {0}; {1} dokončí svůj postup</translation>
    </message>
    <message>
        <source>The drill has no stop command: {0} queued command(s) dropped</source>
        <translation>Vrtačka nemá příkaz k zastavení: zahozeno příkazů ve frontě: {0}</translation>
    </message>
    <message>
        <source>Not sent: {0} is not a drill command ({1})</source>
        <extracomment>Seconds the device has to acknowledge (``R``) a command: it does so in its next cycle. A reply is late (the link shown stale) after this share of the receipt&apos;s time. The largest position the wire carries (six digits, docs/protocols.md §3.2).</extracomment>
        <translation>Neodesláno: {0} není příkaz vrtačky ({1})</translation>
    </message>
    <message>
        <source>Motion refused: {0} is no drill position (0…{1})</source>
        <translation>Pohyb odmítnut: {0} není poloha vrtačky (0…{1})</translation>
    </message>
    <message>
        <source>Link lost: {0}; {1} command(s) dropped</source>
        <translation>Spojení ztraceno: {0}; zahozeno příkazů: {1}</translation>
    </message>
    <message>
        <source>Link lost: {0}</source>
        <translation>Spojení ztraceno: {0}</translation>
    </message>
    <message>
        <source>; {0} command(s) dropped</source>
        <translation>; zahozeno příkazů: {0}</translation>
    </message>
    <message>
        <source>home</source>
        <extracomment>The ``D`` may take this much longer than expected (x) and then this many seconds more. A reply is late (the link shown stale) this long after a procedure&apos;s expected end (the receipt&apos;s share is in :mod:`app.machines.drill.queue`). Sent once a link opens, to hear the drill answer: no command has this letter. What each procedure is called in messages.</extracomment>
        <translation>referenční jízda</translation>
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
        <translation>vrtání</translation>
    </message>
    <message>
        <source>pen down</source>
        <translation>pero dolů</translation>
    </message>
    <message>
        <source>pen up</source>
        <translation>pero nahoru</translation>
    </message>
    <message>
        <source>park</source>
        <translation>parkování</translation>
    </message>
    <message>
        <source>axis {0}</source>
        <translation>osu {0}</translation>
    </message>
    <message>
        <source>moves of {0}</source>
        <extracomment>Seconds of motion in one step of a held jog: what may still run after a release. With Shift (the other speed) a held jog&apos;s steps are this share as long: fine positioning.</extracomment>
        <translation>pohyby {0}</translation>
    </message>
    <message>
        <source>{0} is at the end of its travel</source>
        <translation>{0} je na konci rozsahu pojezdu</translation>
    </message>
    <message>
        <source>Jog ends: the end of the travel</source>
        <translation>Posuv končí: konec rozsahu pojezdu</translation>
    </message>
    <message>
        <source>Garbage from the drill dropped: {0}</source>
        <translation>Nesmyslná data od vrtačky zahozena: {0}</translation>
    </message>
    <message>
        <source>Unexpected reply {0} from the drill (waiting for {1})</source>
        <translation>Nečekaná odpověď {0} od vrtačky (čeká se na {1})</translation>
    </message>
    <message>
        <source>Unexpected reply {0} from the drill</source>
        <translation>Nečekaná odpověď {0} od vrtačky</translation>
    </message>
    <message>
        <source>{0}: it {1}</source>
        <translation>{0}: vrtačka {1}</translation>
    </message>
    <message>
        <source>The drill {0} ({1})</source>
        <translation>Vrtačka {0} ({1})</translation>
    </message>
    <message>
        <source>The drill refused {0} ({1})</source>
        <translation>Vrtačka odmítla {0} ({1})</translation>
    </message>
    <message>
        <source>; {0} queued command(s) dropped</source>
        <translation>; zahozeno příkazů ve frontě: {0}</translation>
    </message>
    <message>
        <source>acknowledged twice: the command or its answer was repeated on the way</source>
        <extracomment>Procedures whose second run leaves the machine where one run does (absolute positions, a pen position, homing, parking): repeating them changes nothing on the board. ``R`` heard once more than sent, per letter: their ``D`` is still to come. The letter of the last procedure the station saw finish (a ``D`` repeated on the way). Commands in flight when the link went or fell silent: their R and D may still come.</extracomment>
        <translation>potvrdila příkaz dvakrát: příkaz nebo odpověď se cestou zopakovaly</translation>
    </message>
    <message>
        <source>finished a procedure the station did not send</source>
        <translation>dokončila proceduru, kterou stanice neposlala</translation>
    </message>
    <message>
        <source>received a command the station did not send (a line changed on the way)</source>
        <translation>přijala příkaz, který stanice neposlala (řádek se cestou změnil)</translation>
    </message>
</context>
<context>
    <name>DrillStepBox</name>
    <message>
        <source>Step through the job (teaching)</source>
        <extracomment>The most characters of a file line shown (the whole line is in its tooltip). The stop&apos;s position (x, y) in the job&apos;s millimetres, or None: the preview rings it.</extracomment>
        <translation>Krokování úlohy (výuka)</translation>
    </message>
    <message>
        <source>Previous line</source>
        <translation>Předchozí řádek</translation>
    </message>
    <message>
        <source>Back one line of the job&apos;s file</source>
        <translation>O řádek zpět v souboru úlohy</translation>
    </message>
    <message>
        <source>Next line</source>
        <translation>Další řádek</translation>
    </message>
    <message>
        <source>Read the next line of the job&apos;s file (Načti řádek)</source>
        <translation>Načíst další řádek souboru úlohy (Načti řádek)</translation>
    </message>
    <message>
        <source>{0} not sent: not connected</source>
        <translation>{0} neodesláno: nepřipojeno</translation>
    </message>
    <message>
        <source>{0} not sent: {1}</source>
        <translation>{0} neodesláno: {1}</translation>
    </message>
    <message>
        <source>{0} sent</source>
        <translation>{0} odesláno</translation>
    </message>
    <message>
        <source>No job loaded: open an Excellon file in the Jobs dock</source>
        <translation>Žádná úloha: otevřete soubor Excellon v panelu Úlohy</translation>
    </message>
    <message>
        <source>{0} lines: Next line reads the first</source>
        <translation>{0} řádků: Další řádek načte první</translation>
    </message>
    <message>
        <source>line {0} of {1}, position {2} of {3}</source>
        <translation>řádek {0} z {1}, poloha {2} z {3}</translation>
    </message>
    <message>
        <source>line {0} of {1}</source>
        <translation>řádek {0} z {1}</translation>
    </message>
    <message>
        <source>no coordinates on this line</source>
        <translation>na tomto řádku nejsou souřadnice</translation>
    </message>
    <message>
        <source>{0} {1} mm = {2} µsteps</source>
        <translation>{0} {1} mm = {2} µkroků</translation>
    </message>
    <message>
        <source>Send {0} to the drill</source>
        <translation>Poslat {0} vrtačce</translation>
    </message>
</context>
<context>
    <name>DrillTiming</name>
    <message>
        <source>X step period</source>
        <extracomment>Each constant: its name, its caption, its unit, the factor from the constant&apos;s unit to the field&apos;s (seconds are shown in ms), and the field&apos;s decimals.</extracomment>
        <translation>Perioda kroku X</translation>
    </message>
    <message>
        <source>Y step period</source>
        <translation>Perioda kroku Y</translation>
    </message>
    <message>
        <source>Z step period</source>
        <translation>Perioda kroku Z</translation>
    </message>
    <message>
        <source>Pause going down</source>
        <translation>Prodleva při spouštění</translation>
    </message>
    <message>
        <source>… after every</source>
        <translation>… po každých</translation>
    </message>
    <message>
        <source>Wait at the bottom</source>
        <translation>Čekání dole</translation>
    </message>
    <message>
        <source>Wait after the return</source>
        <translation>Čekání po návratu</translation>
    </message>
    <message>
        <source>Return stroke</source>
        <translation>Zpětný zdvih</translation>
    </message>
    <message>
        <source>full steps</source>
        <translation>celých kroků</translation>
    </message>
</context>
<context>
    <name>DrillTimingBox</name>
    <message>
        <source>Timing constants (teaching)</source>
        <extracomment>The operator applied constants (a DrillTiming), or went back to the profile&apos;s (None).</extracomment>
        <translation>Časovací konstanty (výuka)</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Použít</translation>
    </message>
    <message>
        <source>Count with these constants: the estimate, the timeouts, the emulator</source>
        <translation>Počítat s těmito konstantami: odhad, časové limity, emulátor</translation>
    </message>
    <message>
        <source>Profile values</source>
        <translation>Hodnoty profilu</translation>
    </message>
    <message>
        <source>Back to the machine profile&apos;s constants</source>
        <translation>Zpět na konstanty profilu stroje</translation>
    </message>
</context>
<context>
    <name>DynamicsPanel</name>
    <message>
        <source>Parameter</source>
        <extracomment>What the last Apply or snapshot load replaced: (axis, parameter type, wire value). The open &quot;write these differences?&quot; question, while it is asked.</extracomment>
        <translation>Parametr</translation>
    </message>
    <message>
        <source>Read</source>
        <extracomment>Each axis has its own column of parameter names: side by side only the first axis&apos;s is shown, stacked each axis block has its own.</extracomment>
        <translation>Načíst</translation>
    </message>
    <message>
        <source>Read every parameter from the device into the fields</source>
        <translation>Načíst všechny parametry ze zařízení do polí</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Použít</translation>
    </message>
    <message>
        <source>Write the edited values to the device; it confirms each one</source>
        <translation>Zapsat upravené hodnoty do zařízení; každou potvrdí</translation>
    </message>
    <message>
        <source>Save snapshot…</source>
        <translation>Uložit zálohu…</translation>
    </message>
    <message>
        <source>Save every stored parameter to a TOML file</source>
        <translation>Uložit všechny uložené parametry do souboru TOML</translation>
    </message>
    <message>
        <source>Load snapshot…</source>
        <translation>Načíst zálohu…</translation>
    </message>
    <message>
        <source>Show what a snapshot changes, then write only that</source>
        <translation>Ukázat, co záloha změní, a zapsat jen to</translation>
    </message>
    <message>
        <source>Undo last write</source>
        <translation>Vrátit poslední zápis</translation>
    </message>
    <message>
        <source>Write back what the last Apply or load replaced</source>
        <translation>Zapsat zpět, co poslední Použít nebo načtení přepsalo</translation>
    </message>
    <message>
        <source>Read only: measured by the device</source>
        <translation>Jen ke čtení: měří zařízení</translation>
    </message>
    <message>
        <source>; at most the mechanical travel, {0} mm</source>
        <translation>; nejvýše mechanický rozsah pojezdu, {0} mm</translation>
    </message>
    <message>
        <source>; current scale CS, the motor gets IRMS = (CS+1)/32 · VFS/(Rsense+20 mΩ)/√2 (VFS {0} V, Rsense {1} Ω)</source>
        <translation>; proudová škála CS, motor dostává IRMS = (CS+1)/32 · VFS/(Rsense+20 mΩ)/√2 (VFS {0} V, Rsense {1} Ω)</translation>
    </message>
    <message>
        <source>; → the speed the step timer really runs, where its whole prescaler and reload values cannot give this one</source>
        <translation>; → rychlost, kterou krokový časovač skutečně jede, když ji jeho celočíselná předdělička a hodnota přetečení nedokážou nastavit přesně</translation>
    </message>
    <message>
        <source>Reading from the device…</source>
        <translation>Načítám ze zařízení…</translation>
    </message>
    <message>
        <source>not a number</source>
        <translation>není číslo</translation>
    </message>
    <message>
        <source>✗ not sent</source>
        <translation>✗ neodesláno</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) written</source>
        <translation>
            <numerusform>zapsána %n hodnota</numerusform>
            <numerusform>zapsány %n hodnoty</numerusform>
            <numerusform>zapsáno %n hodnot</numerusform>
        </translation>
    </message>
    <message>
        <source>not sent: {0}</source>
        <translation>neodesláno: {0}</translation>
    </message>
    <message>
        <source>Nothing changed</source>
        <translation>Nic se nezměnilo</translation>
    </message>
    <message>
        <source>Save parameter snapshot</source>
        <translation>Uložit zálohu parametrů</translation>
    </message>
    <message>
        <source>Parameter snapshots (*.toml)</source>
        <translation>Zálohy parametrů (*.toml)</translation>
    </message>
    <message>
        <source>Load parameter snapshot</source>
        <translation>Načíst zálohu parametrů</translation>
    </message>
    <message>
        <source>Not saved: not read yet: {0} — press Read</source>
        <translation>Neuloženo: zatím nenačteno: {0} — stiskněte Načíst</translation>
    </message>
    <message>
        <source>Not saved: {0}</source>
        <translation>Neuloženo: {0}</translation>
    </message>
    <message>
        <source>Snapshot saved to {0}</source>
        <translation>Záloha uložena do {0}</translation>
    </message>
    <message>
        <source>Not loaded: {0}</source>
        <translation>Nenačteno: {0}</translation>
    </message>
    <message>
        <source>{0}: the device already holds every value</source>
        <translation>{0}: zařízení už má všechny hodnoty</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) of {0} differ from the device:</source>
        <translation>
            <numerusform>%n hodnota z {0} se liší od zařízení:</numerusform>
            <numerusform>%n hodnoty z {0} se liší od zařízení:</numerusform>
            <numerusform>%n hodnot z {0} se liší od zařízení:</numerusform>
        </translation>
    </message>
    <message>
        <source>This snapshot is of another machine ({0}, firmware {1}, {2}), not {3}.</source>
        <translation>Tato záloha je z jiného stroje ({0}, firmware {1}, {2}), ne z {3}.</translation>
    </message>
    <message>
        <source>Write anyway</source>
        <translation>Přesto zapsat</translation>
    </message>
    <message numerus="yes">
        <source>Write %n</source>
        <translation>
            <numerusform>Zapsat %n</numerusform>
            <numerusform>Zapsat %n</numerusform>
            <numerusform>Zapsat %n</numerusform>
        </translation>
    </message>
    <message>
        <source>Snapshot not loaded</source>
        <translation>Záloha nenačtena</translation>
    </message>
    <message>
        <source>Not written: not connected</source>
        <translation>Nezapsáno: nepřipojeno</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) written from the snapshot; the device confirms each</source>
        <translation>
            <numerusform>Ze zálohy zapsána %n hodnota; zařízení ji potvrdí</numerusform>
            <numerusform>Ze zálohy zapsány %n hodnoty; zařízení každou potvrdí</numerusform>
            <numerusform>Ze zálohy zapsáno %n hodnot; zařízení každou potvrdí</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) written back</source>
        <translation>
            <numerusform>zpět zapsána %n hodnota</numerusform>
            <numerusform>zpět zapsány %n hodnoty</numerusform>
            <numerusform>zpět zapsáno %n hodnot</numerusform>
        </translation>
    </message>
    <message>
        <source>• edited</source>
        <translation>• upraveno</translation>
    </message>
    <message>
        <source>… writing</source>
        <translation>… zapisuji</translation>
    </message>
    <message>
        <source>✓ confirmed</source>
        <translation>✓ potvrzeno</translation>
    </message>
    <message>
        <source>✗ refused, kept {0}</source>
        <translation>✗ odmítnuto, ponecháno {0}</translation>
    </message>
    <message>
        <source>Asked for {0}</source>
        <translation>Požadováno {0}</translation>
    </message>
</context>
<context>
    <name>EchoComposer</name>
    <message>
        <source>Inject echo</source>
        <translation>Vložit echo</translation>
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
        <translation>µm, µm/s nebo hodnota</translation>
    </message>
    <message>
        <source>Subscriber ID: pick one, or type any hex ID 00…FF</source>
        <translation>ID odběratele: vyberte nebo napište libovolné hex ID 00…FF</translation>
    </message>
    <message>
        <source>subscriber value</source>
        <translation>hodnota odběratele</translation>
    </message>
    <message>
        <source>Inject</source>
        <translation>Vložit</translation>
    </message>
    <message>
        <source>Fold this echo into the model as if the device had sent it</source>
        <translation>Promítnout toto echo do modelu, jako by ho poslalo zařízení</translation>
    </message>
    <message>
        <source>A whole number, {0}</source>
        <translation>Celé číslo, {0}</translation>
    </message>
    <message>
        <source>Injected {0}</source>
        <translation>Vloženo {0}</translation>
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
        <translation>Není připojen žádný emulátor: tyto ovládací prvky působí na vestavěný emulátor. Zapněte Simulaci nebo ho připojte na stránce Spojení.</translation>
    </message>
    <message>
        <source>Charger connected</source>
        <translation>Nabíječka připojena</translation>
    </message>
    <message>
        <source>USB connected</source>
        <translation>USB připojeno</translation>
    </message>
    <message>
        <source>FRAM verification fault (writes refused)</source>
        <translation>Chyba ověření FRAM (zápisy odmítnuty)</translation>
    </message>
    <message>
        <source>State of charge; below 5 % the stage blocks motion</source>
        <translation>Stav nabití; pod 5 % stolek blokuje pohyb</translation>
    </message>
    <message>
        <source>Board temperature</source>
        <translation>Teplota desky</translation>
    </message>
    <message>
        <source>Platform rotation rate; the IMU&apos;s yaw integrates it</source>
        <translation>Rychlost otáčení plošiny; IMU ji integruje do natočení</translation>
    </message>
    <message>
        <source>Battery</source>
        <translation>Baterie</translation>
    </message>
    <message>
        <source>Temperature</source>
        <translation>Teplota</translation>
    </message>
    <message>
        <source>Rotation rate</source>
        <translation>Rychlost otáčení</translation>
    </message>
    <message>
        <source>{0} end switch</source>
        <extracomment>How often the log view takes in what arrived: fast enough to feel live, slow enough that a 1 kHz stream costs ten redraws a second. Lines the view keeps; the log itself keeps :data:`LOG_CAPACITY` entries (saved in full).</extracomment>
        <translation>{0} koncový spínač</translation>
    </message>
    <message>
        <source>Low</source>
        <translation>Dolní</translation>
    </message>
    <message>
        <source>Close {0}&apos;s low end switch where the axis is now</source>
        <translation>Sepnout dolní koncový spínač osy {0} tam, kde osa právě je</translation>
    </message>
    <message>
        <source>High</source>
        <translation>Horní</translation>
    </message>
    <message>
        <source>Close {0}&apos;s high end switch where the axis is now</source>
        <translation>Sepnout horní koncový spínač osy {0} tam, kde osa právě je</translation>
    </message>
    <message>
        <source>Driver fault</source>
        <translation>Porucha budiče</translation>
    </message>
    <message>
        <source>Over-temperature or stall on {0}&apos;s driver: the axis stops dead</source>
        <translation>Přehřátí nebo zablokování budiče osy {0}: osa se okamžitě zastaví</translation>
    </message>
    <message>
        <source>Drop link</source>
        <translation>Přerušit spojení</translation>
    </message>
    <message>
        <source>Cut the emulated cable; the station reconnects with back-off</source>
        <translation>Přestřihnout emulovaný kabel; stanice se znovu připojí s prodlevami</translation>
    </message>
    <message>
        <source>Corrupt</source>
        <translation>Poškodit</translation>
    </message>
    <message>
        <source>Flip a byte in each of the next frames from the device</source>
        <translation>Změnit jeden bajt v každém z dalších rámců ze zařízení</translation>
    </message>
</context>
<context>
    <name>FrameLogView</name>
    <message>
        <source>Filter: words that must all occur, e.g. rx charger</source>
        <translation>Filtr: slova, která se musí všechna vyskytovat, např. rx charger</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pozastavit</translation>
    </message>
    <message>
        <source>Freeze the view; frames are still recorded and appear on Resume</source>
        <translation>Zmrazit výpis; rámce se dál zaznamenávají a objeví se po Pokračovat</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Vymazat</translation>
    </message>
    <message>
        <source>Save…</source>
        <translation>Uložit…</translation>
    </message>
    <message>
        <source>Save the entries that pass the filter (all when empty)</source>
        <translation>Uložit záznamy, které projdou filtrem (prázdný filtr: všechny)</translation>
    </message>
    <message>
        <source>Frames sent (TX), received (RX), injected (INJ), rejected (BAD)</source>
        <translation>Odeslané (TX), přijaté (RX), vložené (INJ) a odmítnuté (BAD) rámce</translation>
    </message>
    <message numerus="yes">
        <source>… %n entries not shown: the log keeps the last {0}</source>
        <translation>
            <numerusform>… %n záznam nezobrazen: protokol uchovává posledních {0}</numerusform>
            <numerusform>… %n záznamy nezobrazeny: protokol uchovává posledních {0}</numerusform>
            <numerusform>… %n záznamů nezobrazeno: protokol uchovává posledních {0}</numerusform>
        </translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Pokračovat</translation>
    </message>
    <message numerus="yes">
        <source>%n entries</source>
        <translation>
            <numerusform>%n záznam</numerusform>
            <numerusform>%n záznamy</numerusform>
            <numerusform>%n záznamů</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source> — paused, %n new not shown</source>
        <translation>
            <numerusform> — pozastaveno, %n nový nezobrazen</numerusform>
            <numerusform> — pozastaveno, %n nové nezobrazeny</numerusform>
            <numerusform> — pozastaveno, %n nových nezobrazeno</numerusform>
        </translation>
    </message>
    <message>
        <source>Save frame log</source>
        <translation>Uložit protokol rámců</translation>
    </message>
    <message>
        <source>Log files (*.log *.txt);;All files (*)</source>
        <translation>Protokoly (*.log *.txt);;Všechny soubory (*)</translation>
    </message>
    <message>
        <source>Could not save: {0}</source>
        <translation>Nelze uložit: {0}</translation>
    </message>
    <message numerus="yes">
        <source>Saved %n entries to {0}</source>
        <translation>
            <numerusform>Uložen %n záznam do {0}</numerusform>
            <numerusform>Uloženy %n záznamy do {0}</numerusform>
            <numerusform>Uloženo %n záznamů do {0}</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>FrameWords</name>
    <message>
        <source>ok: the oldest unanswered line was accepted</source>
        <translation>ok: nejstarší nezodpovězený řádek přijat</translation>
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
        <translation>, volných bloků plánovače: {0}</translation>
    </message>
    <message>
        <source>the board (re)started: &quot;{0}&quot;</source>
        <translation>deska (znovu) nastartovala: &quot;{0}&quot;</translation>
    </message>
    <message>
        <source>message: &quot;{0}&quot;</source>
        <translation>zpráva: &quot;{0}&quot;</translation>
    </message>
    <message>
        <source>home both axes</source>
        <extracomment>What each drill command letter does (docs/protocols.md, the drill).</extracomment>
        <translation>referenční jízda obou os</translation>
    </message>
    <message>
        <source>move X to {0} µsteps</source>
        <translation>X na {0} µkroků</translation>
    </message>
    <message>
        <source>move Y to {0} µsteps</source>
        <translation>Y na {0} µkroků</translation>
    </message>
    <message>
        <source>drill a hole</source>
        <translation>vyvrtat otvor</translation>
    </message>
    <message>
        <source>pen down</source>
        <translation>pero dolů</translation>
    </message>
    <message>
        <source>pen up</source>
        <translation>pero nahoru</translation>
    </message>
    <message>
        <source>park</source>
        <translation>parkovat</translation>
    </message>
    <message>
        <source>{0} received</source>
        <translation>{0} přijat</translation>
    </message>
    <message>
        <source>{0} done</source>
        <translation>{0} hotov</translation>
    </message>
    <message>
        <source>{0} refused (error)</source>
        <translation>{0} odmítnut (chyba)</translation>
    </message>
    <message>
        <source>directions {0}</source>
        <translation>směry {0}</translation>
    </message>
    <message>
        <source>move {0} by {1} counts</source>
        <translation>posun {0} o {1} dílků</translation>
    </message>
    <message>
        <source>step sizes {0}</source>
        <translation>velikosti kroku {0}</translation>
    </message>
    <message>
        <source>threads {0}</source>
        <translation>závity {0}</translation>
    </message>
    <message>
        <source>every axis is zero where it stands</source>
        <translation>každá osa má nulu tam, kde stojí</translation>
    </message>
    <message>
        <source>ask for the step sizes and threads</source>
        <translation>dotaz na velikosti kroku a závity</translation>
    </message>
    <message>
        <source>stop every axis</source>
        <translation>zastavit všechny osy</translation>
    </message>
    <message>
        <source>{0} stands at {1} counts</source>
        <translation>{0} stojí na {1} dílcích</translation>
    </message>
    <message>
        <source>the unit did not understand a command</source>
        <translation>jednotka nerozuměla příkazu</translation>
    </message>
</context>
<context>
    <name>Gamepad</name>
    <message>
        <source>Gamepad {0} unplugged: jog stopped</source>
        <translation>Gamepad {0} odpojen: ruční posuv zastaven</translation>
    </message>
    <message>
        <source>Gamepad: left stick + shoulder button (held)</source>
        <translation>Gamepad: levá páčka + ramenní tlačítko (držené)</translation>
    </message>
    <message>
        <source>Jog X and Y while both are held; pushed further, faster (G-code boards)</source>
        <translation>Posuv v osách X a Y, dokud jsou obě držena; páčka vychýlená dál = rychleji (G-kódové desky)</translation>
    </message>
    <message>
        <source>Gamepad: right stick up/down + shoulder button</source>
        <translation>Gamepad: pravá páčka nahoru/dolů + ramenní tlačítko</translation>
    </message>
    <message>
        <source>Jog Z while both are held, on machines with a Z axis</source>
        <translation>Posuv v ose Z, dokud jsou obě držena, u strojů s osou Z</translation>
    </message>
    <message>
        <source>Joystick: stick + trigger (held)</source>
        <translation>Joystick: páka + spoušť (držené)</translation>
    </message>
    <message>
        <source>Jog X and Y while both are held</source>
        <translation>Posuv v osách X a Y, dokud jsou obě držena</translation>
    </message>
    <message>
        <source>Let go of the stick or the button, or unplug</source>
        <translation>Pustit páčku nebo tlačítko, nebo odpojit</translation>
    </message>
    <message>
        <source>The jog stops at once</source>
        <translation>Posuv se okamžitě zastaví</translation>
    </message>
    <message>
        <source>&amp;Gamepad…</source>
        <translation>&amp;Gamepad…</translation>
    </message>
    <message>
        <source>Gamepad unavailable: {0}</source>
        <translation>Gamepad není k dispozici: {0}</translation>
    </message>
    <message>
        <source>Gamepad: off</source>
        <translation>Gamepad: vypnut</translation>
    </message>
    <message>
        <source>Gamepad: starting…</source>
        <translation>Gamepad: spouští se…</translation>
    </message>
    <message>
        <source>Gamepad: {0}</source>
        <translation>Gamepad: {0}</translation>
    </message>
    <message>
        <source>Gamepad: waiting for {0}</source>
        <translation>Gamepad: čeká se na {0}</translation>
    </message>
    <message>
        <source>Gamepad: none plugged in</source>
        <translation>Gamepad: žádný není připojen</translation>
    </message>
    <message>
        <source>StepDeck — gamepad</source>
        <translation>StepDeck — gamepad</translation>
    </message>
    <message>
        <source>&amp;Jog with a gamepad or joystick</source>
        <translation>&amp;Ruční posuv gamepadem nebo joystickem</translation>
    </message>
    <message>
        <source>&amp;Device:</source>
        <translation>&amp;Zařízení:</translation>
    </message>
    <message>
        <source>The first one found</source>
        <translation>První nalezené</translation>
    </message>
    <message>
        <source>Nothing jogs unless the enable button is held with the stick: a dropped pad or a drifting stick moves nothing. The pad jogs only while a StepDeck window is active, and a job under way refuses it as it refuses the keys.</source>
        <translation>Nic se nepohne, dokud není s páčkou drženo i povolovací tlačítko: upuštěný gamepad ani ujíždějící páčka strojem nepohnou. Gamepad posouvá jen tehdy, je-li aktivní okno StepDecku, a probíhající úloha ho odmítne stejně jako klávesy.</translation>
    </message>
</context>
<context>
    <name>GcodeDriver</name>
    <message>
        <source>The machine holds (a feed hold: its hold button, the Hold button here, or a &apos;!&apos; that reached it on the wire): the job is paused at {0}. Resume lets it go on (cycle start).</source>
        <extracomment>Station-clock seconds between checkpoint writes while lines stream (each write is an fsync). Station-clock seconds between &quot;operation under way&quot; announcements while lines stream. The modal words a program is checked in (absolute, millimetres, XY plane), sent before its first line where the machine has them: a jog or a console line may have changed them. The work offset when the job began: program coordinates are machine less it. Where the machine stood when the job began, in the program&apos;s coordinates (None when the run began elsewhere than operation 0): standing there again after a fault may mean nothing ran as well as that the file came back to it. The running job&apos;s way to the wire (None without a stream or a session). The last ``[GC:…]`` heard while the set-up is confirmed, awaiting its line&apos;s ``ok``. Checkpoints while lines stream, and &quot;operation under way&quot; announcements, are paced. ``$G`` was sent after the set-up: nothing of the job goes before its answer. The operation the last resume went back to (a refused way back fails there). Set-up and way-back lines sent and not yet answered: the job waits for them, so that none of its lines runs on a machine they did not set up. A pause took back the set-up before it went: it goes again first on the resume. The board reset itself since the job began or last resumed: its position is lost. The operation the operator chose to resume from (ResumeChoice), not yet gone on. A ResumeChoice waits for the operator&apos;s pick. Judges whether the board stands before anything of a resume goes (see standing.py). The board went into a feed hold the station did not ask for (its hold button, or a ``!`` that reached it on the wire): the job is paused, and its resume is a cycle start — the board still has every line it was sent. The operator&apos;s chosen start (its state rebuilt once the machine is looked at). follows ALARM:3 with its banner) is kept for the Resume, not said again.</extracomment>
        <translation>Stroj stojí ve zdržení (feed hold: jeho tlačítko, zdejší tlačítko Zdržet, nebo znak „!“, který k němu dorazil po vedení): úloha je pozastavena na {0}. Pokračovat ji nechá jet dál (cycle start).</translation>
    </message>
    <message>
        <source>The machine restarted during the job (its reset button, its power, or its port reopened) and may have lost its position: the job is paused. Home it ($H) or check where the tool is (clear an alarm with $X), then choose the line to resume from; {0} operation(s) from {1} were sent but not proven run.</source>
        <translation>Stroj se během úlohy restartoval (tlačítkem reset, napájením nebo znovuotevřením portu) a mohl ztratit svou polohu: úloha je pozastavena. Najeďte s ním do výchozí polohy ($H) nebo zkontrolujte, kde je nástroj (alarm zrušte pomocí $X), a pak zvolte řádek, od kterého pokračovat; {0} operací od {1} bylo odesláno, ale jejich provedení není prokázáno.</translation>
    </message>
    <message>
        <source>{0} operation(s) from {1} were sent but their running is not proven: choose the line to resume from (the candidates are highlighted).</source>
        <translation>{0} operací od {1} bylo odesláno, ale jejich provedení není prokázáno: zvolte řádek, od kterého pokračovat (kandidáti jsou zvýrazněni).</translation>
    </message>
    <message>
        <source>Some of them draw: resuming too early draws a stroke twice, too late leaves one out.</source>
        <translation>Některé z nich kreslí: pokračování příliš brzy nakreslí tah dvakrát, příliš pozdě jeden vynechá.</translation>
    </message>
    <message>
        <source>The machine is in alarm: the job stays paused. Check the machine, clear the alarm (home it with $H, or unlock it with $X if its position is still right), then Resume.</source>
        <translation>Stroj je v alarmu: úloha zůstává pozastavená. Zkontrolujte stroj, zrušte alarm (najetím do výchozí polohy příkazem $H, nebo odemčením příkazem $X, pokud jeho poloha stále odpovídá) a pak dejte Pokračovat.</translation>
    </message>
    <message>
        <source>The machine went into alarm {0} ({1}) during the job and stopped: the job is paused at {2}. Clear the alarm (home it with $H, or unlock it with $X if its position is still right), then Resume: the job goes on from what is proven run.</source>
        <translation>Stroj během úlohy přešel do alarmu {0} ({1}) a zastavil se: úloha je pozastavena na {2}. Zrušte alarm (najeďte do výchozí polohy pomocí $H, nebo ho odemkněte pomocí $X, je-li jeho poloha stále správná), pak Pokračovat: úloha pokračuje od toho, co je prokazatelně provedeno.</translation>
    </message>
</context>
<context>
    <name>GcodeEmulatorBox</name>
    <message>
        <source>Emulated board</source>
        <translation>Emulovaná deska</translation>
    </message>
    <message>
        <source>Hold</source>
        <translation>Pozastavit</translation>
    </message>
    <message>
        <source>The board&apos;s feed-hold button</source>
        <translation>Tlačítko pozastavení posuvu na desce</translation>
    </message>
    <message>
        <source>Cycle start</source>
        <translation>Start cyklu</translation>
    </message>
    <message>
        <source>The board&apos;s cycle-start button</source>
        <translation>Tlačítko startu cyklu na desce</translation>
    </message>
    <message>
        <source>ALARM code (1: hard limit, 2: soft limit, 3: reset in motion…)</source>
        <translation>Kód ALARM (1: koncový spínač, 2: softwarový limit, 3: reset za pohybu…)</translation>
    </message>
    <message>
        <source>Raise alarm</source>
        <translation>Vyvolat alarm</translation>
    </message>
    <message>
        <source>ALARM code</source>
        <translation>Kód ALARM</translation>
    </message>
    <message>
        <source>White button</source>
        <translation>Bílé tlačítko</translation>
    </message>
    <message>
        <source>The winder&apos;s white button: the first press switches the holding current off (turn the axes by hand), the second sets the zero there (X = board radius)</source>
        <translation>Bílé tlačítko navíječky: první stisknutí vypne udržovací proud (osami lze otáčet rukou), druhé tam nastaví nulu (X = poloměr desky)</translation>
    </message>
    <message>
        <source>Turn {0} by hand (its driver must be off)</source>
        <translation>Otočit osou {0} rukou (její driver musí být vypnutý)</translation>
    </message>
    <message>
        <source>drivers off: turn the axes by hand, then press again</source>
        <translation>drivery vypnuty: otočte osami rukou a stiskněte znovu</translation>
    </message>
    <message>
        <source>zero set here (X = board radius)</source>
        <translation>nula nastavena zde (X = poloměr desky)</translation>
    </message>
    <message>
        <source>ignored: the machine is busy</source>
        <translation>ignorováno: stroj pracuje</translation>
    </message>
    <message>
        <source>{0} holds: its driver is on</source>
        <translation>{0} drží: její driver je zapnutý</translation>
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
        <translation>Reference</translation>
    </message>
    <message>
        <source>Back to the origin ($H or G28)</source>
        <translation>Referenční jízda do počátku ($H nebo G28)</translation>
    </message>
    <message>
        <source>Pen up</source>
        <translation>Pero nahoru</translation>
    </message>
    <message>
        <source>Lift the pen ({0})</source>
        <translation>Zvednout pero ({0})</translation>
    </message>
    <message>
        <source>Pen down</source>
        <translation>Pero dolů</translation>
    </message>
    <message>
        <source>Lower the pen ({0})</source>
        <translation>Spustit pero ({0})</translation>
    </message>
    <message>
        <source>Hold !</source>
        <translation>Pozastavit !</translation>
    </message>
    <message>
        <source>Feed hold: decelerate and stop</source>
        <translation>Pozastavení posuvu: zpomalit a zastavit</translation>
    </message>
    <message>
        <source>Resume ~</source>
        <translation>Pokračovat ~</translation>
    </message>
    <message>
        <source>Carry on after a hold or M0</source>
        <translation>Pokračovat po pozastavení nebo M0</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Reset</translation>
    </message>
    <message>
        <source>Soft reset (Ctrl-X): stop and drop everything buffered</source>
        <translation>Softwarový reset (Ctrl-X): zastavit a zahodit vše ve vyrovnávací paměti</translation>
    </message>
    <message>
        <source>Console</source>
        <translation>Konzole</translation>
    </message>
    <message>
        <source>G0 X10 Y10, $$, M3 …  (Up/Down: history)</source>
        <translation>G0 X10 Y10, $$, M3 …  (Nahoru/Dolů: historie)</translation>
    </message>
    <message>
        <source>Send</source>
        <translation>Odeslat</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Vymazat</translation>
    </message>
    <message>
        <source>Clear the console</source>
        <translation>Vymazat konzoli</translation>
    </message>
    <message>
        <source>Zero by hand</source>
        <extracomment>A GRBL alarm or error explained, with what clears it (hidden without one).</extracomment>
        <translation>Nulování rukou</translation>
    </message>
    <message>
        <source>Release the motors, turn the base and move the needle by hand until nail 0 faces the needle and the needle stands at the board&apos;s edge, then Zero here: A 0, X the board radius, Z 0. Nothing moves.</source>
        <translation>Uvolněte motory, rukou otočte podstavou a posuňte jehlu, až bude hřebík 0 proti jehle a jehla na okraji desky, pak Nula zde: A 0, X poloměr desky, Z 0. Nic se nepohne.</translation>
    </message>
    <message>
        <source>Board radius: X where the needle meets the board&apos;s edge</source>
        <translation>Poloměr desky: X, kde jehla stojí na okraji desky</translation>
    </message>
    <message>
        <source>Release motors</source>
        <translation>Uvolnit motory</translation>
    </message>
    <message>
        <source>Switch every driver off (M18) so the axes turn by hand; refused while a job is under way or the machine moves</source>
        <translation>Vypnout všechny drivery (M18), aby se osami dalo otáčet rukou; odmítnuto, dokud běží úloha nebo se stroj pohybuje</translation>
    </message>
    <message>
        <source>Zero here</source>
        <translation>Nula zde</translation>
    </message>
    <message>
        <source>The axes stand at the zero: A 0, X the board radius, Z 0 (G92); nothing moves</source>
        <translation>Osy stojí na nule: A 0, X poloměr desky, Z 0 (G92); nic se nepohne</translation>
    </message>
    <message>
        <source>Board radius</source>
        <translation>Poloměr desky</translation>
    </message>
    <message>
        <source>Beyond the travel</source>
        <translation>Mimo rozsah pojezdu</translation>
    </message>
    <message>
        <source>{0}.

Send it to the machine anyway?</source>
        <translation>{0}.

Přesto odeslat do stroje?</translation>
    </message>
    <message>
        <source>! {0}: not sent (beyond the travel)</source>
        <translation>! {0}: neodesláno (mimo rozsah pojezdu)</translation>
    </message>
    <message>
        <source>! {0}: not sent</source>
        <translation>! {0}: neodesláno</translation>
    </message>
    <message numerus="yes">
        <source>! soft reset: %n unanswered line(s) dropped</source>
        <translation>
            <numerusform>! softwarový reset: zahozen %n nepotvrzený řádek</numerusform>
            <numerusform>! softwarový reset: zahozeny %n nepotvrzené řádky</numerusform>
            <numerusform>! softwarový reset: zahozeno %n nepotvrzených řádků</numerusform>
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
        <translation>Vložit odpověď (jako by ji poslalo zařízení)</translation>
    </message>
    <message>
        <source>Inject</source>
        <translation>Vložit</translation>
    </message>
    <message>
        <source>Inject {0}</source>
        <translation>Vložit {0}</translation>
    </message>
    <message>
        <source>Not injected: {0}</source>
        <translation>Nevloženo: {0}</translation>
    </message>
    <message>
        <source>banner</source>
        <extracomment>Replies a developer reaches for most, for the pane&apos;s quick buttons.</extracomment>
        <translation>úvodní hlášení</translation>
    </message>
</context>
<context>
    <name>GcodeSession</name>
    <message>
        <source>Stopped: {0} line(s) not run</source>
        <extracomment>A stop resets the device this long after its hold at the latest, standing or not. The stop under way ends a jog: no &quot;lines not run&quot; message for it. When the hold went out, while its reset has not (None: no stop under way). A stop went out and no report since its reset has shown the board standing: on a silent line its hold and reset may both have been lost.</extracomment>
        <translation>Zastaveno: neprovedeno řádků: {0}</translation>
    </message>
    <message>
        <source>Jog ends: the end of the travel</source>
        <extracomment>Each held-arrow step is this much motion, and the next goes only while the device&apos;s planner holds fewer than JOG_BLOCKS_AHEAD blocks. Fraction of an axis&apos;s top speed a held arrow jogs at. A jog step shorter than this (the travel&apos;s end reached) is not sent. Whether the board takes ``$J=`` jogs (0x85 cancels them). Without ``Bf:`` in the reports: when each planned jog step should be done (clock). Where the steps sent so far take each axis (None: no jog under way). A jog cancel was sent and the board still reports Jog: a new jog waits.</extracomment>
        <translation>Posuv končí: konec rozsahu pojezdu</translation>
    </message>
    <message>
        <source>Link lost: {0}; {1} unanswered line(s)</source>
        <translation>Spojení ztraceno: {0}; nepotvrzených řádků: {1}</translation>
    </message>
    <message>
        <source>Link lost: {0}</source>
        <translation>Spojení ztraceno: {0}</translation>
    </message>
    <message>
        <source>Garbage from the device dropped: {0}</source>
        <translation>Nesmyslná data od zařízení zahozena: {0}</translation>
    </message>
    <message>
        <source>Machine alarm {0}: {1}</source>
        <translation>Alarm stroje {0}: {1}</translation>
    </message>
    <message>
        <source>The device reset: {0} unanswered line(s) were not run</source>
        <translation>Zařízení se resetovalo: neprovedeno nezodpovězených řádků: {0}</translation>
    </message>
    <message>
        <source>The device&apos;s replies could not be read ({0}): stopping</source>
        <translation>Odpovědi zařízení nelze přečíst ({0}): zastavuji</translation>
    </message>
    <message>
        <source>A reply arrived for no line (ignored)</source>
        <translation>Přišla odpověď bez řádku (ignorována)</translation>
    </message>
    <message>
        <source>{0} refused: error {1}, {2}</source>
        <translation>{0} odmítnut: chyba {1}, {2}</translation>
    </message>
    <message>
        <source>The board holds {0} byte(s) of a line whose end never came (lost on the way) and waits for it: it stands idle, so it is reset, keeping its position, and what it ran is looked at again</source>
        <extracomment>A line cut on the wire, its start stuck in the board&apos;s buffer (stuck_line.py). The board&apos;s buffer against the bytes counted unanswered (byte_count.py). Planner blocks the device has, learned from its ``Bf:`` reports (0: unknown). The pen (a GRBL plotter&apos;s spindle) against the lines answered (pen_watch.py).</extracomment>
        <translation>Deska drží {0} bajt(ů) řádku, jehož konec nikdy nepřišel (ztratil se cestou), a čeká na něj: stojí v klidu, proto je resetována se zachováním polohy a to, co provedla, se znovu prověří</translation>
    </message>
    <message>
        <source>{0} line(s) unanswered while the board stands idle; waiting for its answer (without Bf: in its reports it cannot show it has them)</source>
        <translation>Nezodpovězených řádků, zatímco deska stojí v klidu: {0}; čeká se na její odpověď (bez Bf: ve zprávách nemůže ukázat, že je má)</translation>
    </message>
    <message>
        <source>{0} line(s) sent never reached the board: it has taken every byte it got and stands idle short of where they end; it is reset, keeping its position, and what it ran is looked at again</source>
        <translation>{0} odeslaných řádků nikdy nedorazilo do desky: převzala každý bajt, který dostala, a stojí v klidu před místem, kde končí; je resetována se zachováním polohy a to, co provedla, se znovu prověří</translation>
    </message>
    <message>
        <source>{0} answer(s) from the board were lost on the way; it has taken and run every line sent, so they count as answered</source>
        <translation>Odpovědí desky ztracených cestou: {0}; převzala a provedla každý odeslaný řádek, takže se počítají jako zodpovězené</translation>
    </message>
    <message>
        <source>The board holds {0} byte(s) more than were sent and not answered (a line or an answer arrived twice on the way): the lines it holds may be garbled, so it is stopped before it runs them</source>
        <translation>Deska drží o {0} bajt(ů) více, než bylo odesláno a nezodpovězeno (řádek nebo odpověď dorazily cestou dvakrát): řádky, které drží, mohou být poškozené, proto je zastavena dříve, než je provede</translation>
    </message>
    <message>
        <source>The board holds {0} byte(s) where the lines sent and not yet run make at least {1}: {2} byte(s) were lost on the way inside a line waiting in its buffer (in “{3}” or a line behind it), so it is stopped before it runs it</source>
        <translation>Deska drží {0} bajt(ů), kde odeslané a dosud neprovedené řádky dávají alespoň {1}: cestou se ztratilo {2} bajt(ů) uvnitř řádku čekajícího v její vyrovnávací paměti (v „{3}“ nebo v řádku za ním), proto je zastavena dříve, než jej provede</translation>
    </message>
    <message>
        <source>; {0} unanswered line(s)</source>
        <translation>; nezodpovězených řádků: {0}</translation>
    </message>
    <message>
        <source>Not sent without confirmation: {0}</source>
        <extracomment>No reply for this long: the link is lost (:mod:`~app.machines.gcode.timing`). Status queries unanswered before the link is shown stale (amber), and the least time. The lines of one write, in order (list[SentLine]): what hears every line of a running job listens here, once a batch, not once a line. Lines of the followed job were answered (counted there): once per batch of replies. A reply line worth showing the operator (the console): its text. The device was reset (banner seen or reset sent): whatever was unanswered is gone. The streaming loop and its ``ok`` accounting, on the transport&apos;s reader thread. Line serials, taken under the feeder&apos;s lock: both threads number lines. A status report since the last line was answered showed the machine idle (written under the feeder&apos;s lock: a job&apos;s line queued on the reader thread clears it). Silence shown amber: a few status queries (one each ``status_ms``) unanswered. GRBL&apos;s lock after a hard or soft limit: silent until a reset (limit_lock.py). Whether the last :attr:`reset` was the board&apos;s own (a banner nobody here asked for: its reset button, a power dip), not a soft reset the station sent. The board&apos;s work coordinate offset last reported (GRBL&apos;s WCO:), None before any. What the followed job had as the last status report was read (its snapshot). After a silence: when the board was first heard again, the first status report made after that had settled, and whether a banner came meanwhile.</extracomment>
        <translation>Bez potvrzení neodesláno: {0}</translation>
    </message>
    <message>
        <source>Not sent: {0} ({1})</source>
        <translation>Neodesláno: {0} ({1})</translation>
    </message>
    <message>
        <source>Not sent: {0} (not connected)</source>
        <translation>Neodesláno: {0} (nepřipojeno)</translation>
    </message>
    <message>
        <source>it restarted meanwhile (its banner came), so what it had is gone</source>
        <translation>mezitím se restartovalo (přišel jeho úvodní text), takže co mělo, je pryč</translation>
    </message>
    <message>
        <source>it is in alarm</source>
        <translation>je v alarmu</translation>
    </message>
    <message>
        <source>{0} line(s) still unanswered while the board stands idle, and its reports cannot show whether it has them: it is reset, keeping its position, and what it ran is looked at again</source>
        <translation>{0} řádek/řádků stále bez odpovědi, zatímco deska stojí nečinně, a její hlášení nemohou ukázat, zda je má: deska se resetuje, poloha zůstává, a co provedla, se posoudí znovu</translation>
    </message>
    <message>
        <source>in alarm: reset to continue</source>
        <extracomment>The alarms after which GRBL waits for a reset (protocol.c): hard and soft limits. GRBL&apos;s words after them (report.c, ``MESSAGE_CRITICAL_EVENT``).</extracomment>
        <translation>v alarmu: pokračujte resetem</translation>
    </message>
</context>
<context>
    <name>GrblAlarmBand</name>
    <message>
        <source>Unlock ($X)</source>
        <translation>Odemknout ($X)</translation>
    </message>
    <message>
        <source>Home ($H)</source>
        <translation>Výchozí poloha ($H)</translation>
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
        <translation>Najeďte stroj do výchozí polohy ($H): jeho poloha je pravděpodobně ztracena.</translation>
    </message>
    <message>
        <source>Check the limit switches and their wiring, then home the machine ($H).</source>
        <translation>Zkontrolujte koncové spínače a jejich zapojení, pak najeďte stroj do výchozí polohy ($H).</translation>
    </message>
    <message>
        <source>Reset the board (Ctrl-X): it answers nothing until then. Check the limit switches, then home the machine ($H), or unlock it ($X) only if its position is surely right.</source>
        <extracomment>After a hard or soft limit GRBL answers nothing until it is reset (limit_lock.py).</extracomment>
        <translation>Resetujte desku (Ctrl-X): do té doby neodpovídá na nic. Zkontrolujte koncové spínače, pak proveďte referenční jízdu ($H), nebo stroj odemkněte ($X), jen pokud je jeho poloha jistě správná.</translation>
    </message>
    <message>
        <source>Reset the board (Ctrl-X): it answers nothing until then. Then unlock it ($X): its position is kept; or home it ($H).</source>
        <translation>Resetujte desku (Ctrl-X): do té doby neodpovídá na nic. Pak stroj odemkněte ($X): jeho poloha zůstala zachována; nebo proveďte referenční jízdu ($H).</translation>
    </message>
    <message>
        <source>Check the probe and its wiring, then unlock ($X).</source>
        <translation>Zkontrolujte sondu a její zapojení, pak odemkněte ($X).</translation>
    </message>
    <message>
        <source>Close the safety door, then home the machine ($H).</source>
        <translation>Zavřete bezpečnostní dvířka, pak najeďte stroj do výchozí polohy ($H).</translation>
    </message>
    <message>
        <source>Correct the line: the board did not run it.</source>
        <translation>Opravte řádek: deska ho neprovedla.</translation>
    </message>
    <message>
        <source>Check the board&apos;s settings ($$).</source>
        <translation>Zkontrolujte nastavení desky ($$).</translation>
    </message>
    <message>
        <source>Wait until the machine stands idle, then send it again.</source>
        <translation>Počkejte, až stroj stojí v klidu, a pošlete příkaz znovu.</translation>
    </message>
    <message>
        <source>Clear the alarm first: home the machine ($H), or unlock it ($X).</source>
        <translation>Nejprve zrušte alarm: najeďte stroj do výchozí polohy ($H), nebo ho odemkněte ($X).</translation>
    </message>
    <message>
        <source>Close the safety door.</source>
        <translation>Zavřete bezpečnostní dvířka.</translation>
    </message>
    <message>
        <source>Jog within the machine&apos;s travel.</source>
        <translation>Posouvejte jen v rozsahu pojezdu stroje.</translation>
    </message>
    <message>
        <source>Hard limit has been triggered. Machine position is likely lost due to sudden halt. Re-homing is highly recommended.</source>
        <translation>Sepnul koncový spínač. Poloha stroje je po náhlém zastavení pravděpodobně ztracena. Důrazně doporučujeme znovu najet do výchozí polohy.</translation>
    </message>
    <message>
        <source>Soft limit alarm. G-code motion target exceeds machine travel. Machine position retained. Alarm may be safely unlocked.</source>
        <translation>Softwarový limit. Cíl pohybu G-kódu leží mimo pojezd stroje. Poloha stroje zůstala zachována. Alarm lze bezpečně odemknout.</translation>
    </message>
    <message>
        <source>Reset while in motion. Machine position is likely lost due to sudden halt. Re-homing is highly recommended.</source>
        <translation>Reset během pohybu. Poloha stroje je po náhlém zastavení pravděpodobně ztracena. Důrazně doporučujeme znovu najet do výchozí polohy.</translation>
    </message>
    <message>
        <source>Probe fail. Probe is not in the expected initial state before starting probe cycle.</source>
        <translation>Chyba sondy. Sonda není před začátkem měřicího cyklu v očekávaném výchozím stavu.</translation>
    </message>
    <message>
        <source>Probe fail. Probe did not contact the workpiece within the programmed travel.</source>
        <translation>Chyba sondy. Sonda se v naprogramované dráze nedotkla obrobku.</translation>
    </message>
    <message>
        <source>Homing fail. The active homing cycle was reset.</source>
        <translation>Chyba najetí do výchozí polohy. Probíhající cyklus byl resetován.</translation>
    </message>
    <message>
        <source>Homing fail. Safety door was opened during homing cycle.</source>
        <translation>Chyba najetí do výchozí polohy. Během cyklu byla otevřena bezpečnostní dvířka.</translation>
    </message>
    <message>
        <source>Homing fail. Pull off travel failed to clear limit switch. Try increasing pull-off setting or check wiring.</source>
        <translation>Chyba najetí do výchozí polohy. Odjezd od spínače ho neuvolnil. Zkuste zvětšit odjezd (pull-off) nebo zkontrolujte zapojení.</translation>
    </message>
    <message>
        <source>Homing fail. Could not find limit switch within search distances. Try increasing max travel, decreasing pull-off distance, or check wiring.</source>
        <translation>Chyba najetí do výchozí polohy. Koncový spínač nebyl v hledané vzdálenosti nalezen. Zkuste zvětšit maximální pojezd, zmenšit odjezd (pull-off) nebo zkontrolujte zapojení.</translation>
    </message>
    <message>
        <source>Homing fail. Second dual axis limit switch failed to trigger within configured search distance after first. Try increasing trigger fail distance or check wiring.</source>
        <translation>Chyba najetí do výchozí polohy. Druhý spínač zdvojené osy nesepnul v nastavené vzdálenosti po prvním. Zkuste zvětšit tuto vzdálenost nebo zkontrolujte zapojení.</translation>
    </message>
    <message>
        <source>G-code words consist of a letter and a value. Letter was not found.</source>
        <translation>Slovo G-kódu tvoří písmeno a hodnota. Písmeno chybí.</translation>
    </message>
    <message>
        <source>Missing the expected G-code word value or numeric value format is not valid.</source>
        <translation>Chybí očekávaná hodnota slova G-kódu nebo číslo nemá platný tvar.</translation>
    </message>
    <message>
        <source>Grbl &apos;$&apos; system command was not recognized or supported.</source>
        <translation>Systémový příkaz &apos;$&apos; GRBL nezná nebo nepodporuje.</translation>
    </message>
    <message>
        <source>Negative value received for an expected positive value.</source>
        <translation>Záporná hodnota tam, kde se očekává kladná.</translation>
    </message>
    <message>
        <source>Homing cycle failure. Homing is not enabled via settings.</source>
        <translation>Najetí do výchozí polohy selhalo. V nastavení není povoleno.</translation>
    </message>
    <message>
        <source>Minimum step pulse time must be greater than 3usec.</source>
        <translation>Nejkratší krokový impulz musí být delší než 3 µs.</translation>
    </message>
    <message>
        <source>An EEPROM read failed. Auto-restoring affected EEPROM to default values.</source>
        <translation>Čtení EEPROM selhalo. Dotčené hodnoty EEPROM se obnovují na výchozí.</translation>
    </message>
    <message>
        <source>Grbl &apos;$&apos; command cannot be used unless Grbl is IDLE. Ensures smooth operation during a job.</source>
        <translation>Příkaz &apos;$&apos; lze použít jen v klidu (Idle). Tak nenaruší běžící úlohu.</translation>
    </message>
    <message>
        <source>G-code commands are locked out during alarm or jog state.</source>
        <translation>Příkazy G-kódu jsou během alarmu nebo ručního posuvu zablokovány.</translation>
    </message>
    <message>
        <source>Soft limits cannot be enabled without homing also enabled.</source>
        <translation>Softwarové limity nelze zapnout bez povoleného najetí do výchozí polohy.</translation>
    </message>
    <message>
        <source>Max characters per line exceeded. Received command line was not executed.</source>
        <translation>Překročen největší počet znaků na řádku. Přijatý řádek nebyl proveden.</translation>
    </message>
    <message>
        <source>Grbl &apos;$&apos; setting value cause the step rate to exceed the maximum supported.</source>
        <translation>Hodnota nastavení &apos;$&apos; by překročila nejvyšší podporovanou krokovou frekvenci.</translation>
    </message>
    <message>
        <source>Safety door detected as opened and door state initiated.</source>
        <translation>Bezpečnostní dvířka jsou otevřena; deska přešla do stavu Door.</translation>
    </message>
    <message>
        <source>Build info or startup line exceeded EEPROM line length limit. Line not stored.</source>
        <translation>Informace o sestavení nebo startovní řádek přesahuje délku řádku v EEPROM. Řádek nebyl uložen.</translation>
    </message>
    <message>
        <source>Jog target exceeds machine travel. Jog command has been ignored.</source>
        <translation>Cíl ručního posuvu leží mimo pojezd stroje. Příkaz byl ignorován.</translation>
    </message>
    <message>
        <source>Jog command has no &apos;=&apos; or contains prohibited g-code.</source>
        <translation>Příkaz ručního posuvu nemá &apos;=&apos; nebo obsahuje zakázaný G-kód.</translation>
    </message>
    <message>
        <source>Laser mode requires PWM output.</source>
        <translation>Laserový režim vyžaduje výstup PWM.</translation>
    </message>
    <message>
        <source>Unsupported or invalid g-code command found in block.</source>
        <translation>Řádek obsahuje nepodporovaný nebo neplatný příkaz G-kódu.</translation>
    </message>
    <message>
        <source>More than one g-code command from same modal group found in block.</source>
        <translation>Řádek obsahuje víc příkazů G-kódu z téže modální skupiny.</translation>
    </message>
    <message>
        <source>Feed rate has not yet been set or is undefined.</source>
        <translation>Rychlost posuvu ještě nebyla nastavena.</translation>
    </message>
    <message>
        <source>G-code command in block requires an integer value.</source>
        <translation>Příkaz G-kódu na řádku vyžaduje celé číslo.</translation>
    </message>
    <message>
        <source>More than one g-code command that requires axis words found in block.</source>
        <translation>Řádek obsahuje víc příkazů G-kódu, které vyžadují slova os.</translation>
    </message>
    <message>
        <source>Repeated g-code word found in block.</source>
        <translation>Řádek obsahuje opakované slovo G-kódu.</translation>
    </message>
    <message>
        <source>No axis words found in block for g-code command or current modal state which requires them.</source>
        <translation>Řádek nemá slova os, která příkaz nebo aktuální modální stav vyžaduje.</translation>
    </message>
    <message>
        <source>Line number value is invalid.</source>
        <translation>Číslo řádku je neplatné.</translation>
    </message>
    <message>
        <source>G-code command is missing a required value word.</source>
        <translation>Příkazu G-kódu chybí povinné slovo s hodnotou.</translation>
    </message>
    <message>
        <source>G59.x work coordinate systems are not supported.</source>
        <translation>Pracovní souřadnicové systémy G59.x nejsou podporovány.</translation>
    </message>
    <message>
        <source>G53 only allowed with G0 and G1 motion modes.</source>
        <translation>G53 je povoleno jen s pohyby G0 a G1.</translation>
    </message>
    <message>
        <source>Axis words found in block when no command or current modal state uses them.</source>
        <translation>Řádek obsahuje slova os, která žádný příkaz ani modální stav nepoužívá.</translation>
    </message>
    <message>
        <source>G2 and G3 arcs require at least one in-plane axis word.</source>
        <translation>Oblouky G2 a G3 vyžadují aspoň jedno slovo osy v rovině.</translation>
    </message>
    <message>
        <source>Motion command target is invalid.</source>
        <translation>Cíl pohybového příkazu je neplatný.</translation>
    </message>
    <message>
        <source>Arc radius value is invalid.</source>
        <translation>Poloměr oblouku je neplatný.</translation>
    </message>
    <message>
        <source>G2 and G3 arcs require at least one in-plane offset word.</source>
        <translation>Oblouky G2 a G3 vyžadují aspoň jedno slovo odsazení v rovině.</translation>
    </message>
    <message>
        <source>Unused value words found in block.</source>
        <translation>Řádek obsahuje nepoužitá slova s hodnotou.</translation>
    </message>
    <message>
        <source>G43.1 dynamic tool length offset is not assigned to configured tool length axis.</source>
        <translation>Dynamická korekce délky nástroje G43.1 není přiřazena k nastavené ose délky nástroje.</translation>
    </message>
    <message>
        <source>Tool number greater than max supported value.</source>
        <translation>Číslo nástroje je větší než největší podporované.</translation>
    </message>
    <message>
        <source>A code GRBL 1.1 does not document.</source>
        <translation>Kód, který dokumentace GRBL 1.1 nezná.</translation>
    </message>
</context>
<context>
    <name>GrblMeaning</name>
    <message>
        <source>expected command letter: a G-code word needs a letter</source>
        <extracomment>The codec&apos;s texts, marked for translation (the same English: lupdate reads these).</extracomment>
        <translation>očekáváno písmeno příkazu: slovo G-kódu potřebuje písmeno</translation>
    </message>
    <message>
        <source>bad number format: a word&apos;s value is missing or malformed</source>
        <translation>chybný formát čísla: hodnota slova chybí nebo je chybná</translation>
    </message>
    <message>
        <source>invalid statement: &apos;$&apos; system command not recognised</source>
        <translation>neplatný příkaz: systémový příkaz &apos;$&apos; nerozpoznán</translation>
    </message>
    <message>
        <source>negative value where a positive one is expected</source>
        <translation>záporná hodnota tam, kde se čeká kladná</translation>
    </message>
    <message>
        <source>setting disabled: homing is not enabled</source>
        <translation>nastavení vypnuto: referenční jízda není povolena</translation>
    </message>
    <message>
        <source>step pulse time must be at least 3 microseconds</source>
        <translation>délka krokového pulzu musí být alespoň 3 mikrosekundy</translation>
    </message>
    <message>
        <source>EEPROM read failed, defaults restored</source>
        <translation>čtení EEPROM selhalo, obnoveny výchozí hodnoty</translation>
    </message>
    <message>
        <source>not idle: this &apos;$&apos; command needs the machine idle</source>
        <translation>není v klidu: tento příkaz &apos;$&apos; vyžaduje stroj v klidu</translation>
    </message>
    <message>
        <source>G-code locked out during alarm or jog</source>
        <translation>G-kód zablokován během alarmu nebo ručního posuvu</translation>
    </message>
    <message>
        <source>soft limits need homing enabled</source>
        <translation>softwarové limity vyžadují povolenou referenční jízdu</translation>
    </message>
    <message>
        <source>line overflow: too many characters in the line, not executed</source>
        <translation>přetečení řádku: příliš mnoho znaků, neprovedeno</translation>
    </message>
    <message>
        <source>setting would exceed the maximum step rate</source>
        <translation>nastavení by překročilo nejvyšší frekvenci kroků</translation>
    </message>
    <message>
        <source>safety door open</source>
        <translation>bezpečnostní dvířka otevřena</translation>
    </message>
    <message>
        <source>line length exceeded: build info or startup line too long to store</source>
        <translation>překročena délka řádku: údaj o sestavení nebo startovací řádek je příliš dlouhý k uložení</translation>
    </message>
    <message>
        <source>travel exceeded: target beyond the machine&apos;s travel, ignored</source>
        <translation>překročen pojezd: cíl mimo pojezd stroje, ignorováno</translation>
    </message>
    <message>
        <source>invalid jog command</source>
        <translation>neplatný příkaz ručního posuvu</translation>
    </message>
    <message>
        <source>laser mode requires PWM output</source>
        <translation>laserový režim vyžaduje výstup PWM</translation>
    </message>
    <message>
        <source>unsupported or invalid G-code command</source>
        <translation>nepodporovaný nebo neplatný příkaz G-kódu</translation>
    </message>
    <message>
        <source>modal group violation: two commands of one modal group in a line</source>
        <translation>porušení modální skupiny: dva příkazy jedné modální skupiny na řádku</translation>
    </message>
    <message>
        <source>undefined feed rate</source>
        <translation>nedefinovaný posuv</translation>
    </message>
    <message>
        <source>command requires an integer value</source>
        <translation>příkaz vyžaduje celé číslo</translation>
    </message>
    <message>
        <source>more than one command in the line needs axis words</source>
        <translation>více než jeden příkaz na řádku potřebuje slova os</translation>
    </message>
    <message>
        <source>repeated word in the line</source>
        <translation>opakované slovo na řádku</translation>
    </message>
    <message>
        <source>no axis words for a command that needs them</source>
        <translation>chybí slova os pro příkaz, který je potřebuje</translation>
    </message>
    <message>
        <source>invalid line number</source>
        <translation>neplatné číslo řádku</translation>
    </message>
    <message>
        <source>command is missing a required value word</source>
        <translation>příkazu chybí povinné slovo s hodnotou</translation>
    </message>
    <message>
        <source>G59.x work coordinate systems are not supported</source>
        <translation>pracovní souřadnicové systémy G59.x nejsou podporovány</translation>
    </message>
    <message>
        <source>G53 only with G0 and G1</source>
        <translation>G53 jen s G0 a G1</translation>
    </message>
    <message>
        <source>axis words that no command uses</source>
        <translation>slova os, která žádný příkaz nepoužívá</translation>
    </message>
    <message>
        <source>G2/G3 arcs need at least one in-plane axis word</source>
        <translation>oblouky G2/G3 potřebují alespoň jedno slovo osy v rovině</translation>
    </message>
    <message>
        <source>motion target is invalid</source>
        <translation>cíl pohybu je neplatný</translation>
    </message>
    <message>
        <source>arc radius is invalid</source>
        <translation>poloměr oblouku je neplatný</translation>
    </message>
    <message>
        <source>G2/G3 arcs need at least one in-plane offset word</source>
        <translation>oblouky G2/G3 potřebují alespoň jedno slovo odsazení v rovině</translation>
    </message>
    <message>
        <source>unused value words in the line</source>
        <translation>nepoužitá slova s hodnotou na řádku</translation>
    </message>
    <message>
        <source>dynamic tool length offset not on the tool length axis</source>
        <translation>dynamická korekce délky nástroje není na ose délky nástroje</translation>
    </message>
    <message>
        <source>tool number greater than supported</source>
        <translation>číslo nástroje větší, než je podporováno</translation>
    </message>
    <message>
        <source>hard limit triggered: position likely lost; reset, then home</source>
        <translation>sepnul koncový spínač: poloha je nejspíš ztracena; resetujte, pak proveďte referenční jízdu</translation>
    </message>
    <message>
        <source>soft limit: target beyond the travel; reset, then unlock or home</source>
        <translation>softwarový limit: cíl mimo pojezd; resetujte, pak odemkněte nebo proveďte referenční jízdu</translation>
    </message>
    <message>
        <source>reset while in motion: position likely lost, re-home</source>
        <translation>reset během pohybu: poloha je nejspíš ztracena, proveďte referenční jízdu</translation>
    </message>
    <message>
        <source>probe fail: probe not in the expected initial state</source>
        <translation>chyba sondy: sonda není v očekávaném výchozím stavu</translation>
    </message>
    <message>
        <source>probe fail: no contact within the programmed travel</source>
        <translation>chyba sondy: žádný dotyk v naprogramované dráze</translation>
    </message>
    <message>
        <source>homing fail: the homing cycle was reset</source>
        <translation>chyba referenční jízdy: cyklus byl resetován</translation>
    </message>
    <message>
        <source>homing fail: safety door opened while homing</source>
        <translation>chyba referenční jízdy: během ní se otevřela bezpečnostní dvířka</translation>
    </message>
    <message>
        <source>homing fail: pull-off did not clear the limit switch</source>
        <translation>chyba referenční jízdy: odjezd neuvolnil koncový spínač</translation>
    </message>
    <message>
        <source>homing fail: limit switch not found within the search distance</source>
        <translation>chyba referenční jízdy: koncový spínač nenalezen v hledané vzdálenosti</translation>
    </message>
    <message>
        <source>unknown error {0}</source>
        <translation>neznámá chyba {0}</translation>
    </message>
    <message>
        <source>unknown alarm {0}</source>
        <translation>neznámý alarm {0}</translation>
    </message>
    <message>
        <source>homing fail: the second switch of a dual axis did not trigger after the first</source>
        <translation>chyba referenční jízdy: druhý spínač zdvojené osy nesepnul po prvním</translation>
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
        <translation>strojová poloha (bez něj: pracovní poloha)</translation>
    </message>
    <message>
        <source>buffer state (Bf:)</source>
        <translation>stav vyrovnávacích pamětí (Bf:)</translation>
    </message>
    <message>
        <source>the station reads positions in millimetres</source>
        <translation>stanice čte polohy v milimetrech</translation>
    </message>
    <message>
        <source>Step pulse time</source>
        <translation>Délka krokového pulzu</translation>
    </message>
    <message>
        <source>How long each step pulse lasts. The stepper drivers name the least they need; GRBL takes no less than 3 µs.</source>
        <translation>Jak dlouho trvá každý krokový pulz. Budiče motorů udávají nejkratší, který potřebují; GRBL nepřijme méně než 3 µs.</translation>
    </message>
    <message>
        <source>Step idle delay</source>
        <translation>Prodleva před uvolněním motorů</translation>
    </message>
    <message>
        <source>How long the motors stay powered after a motion ends, so the axes settle before they are let go. 255 keeps them powered.</source>
        <translation>Jak dlouho zůstanou motory pod proudem po skončení pohybu, aby se osy ustálily, než se uvolní. 255 je nechá pod proudem stále.</translation>
    </message>
    <message>
        <source>Step pulse invert</source>
        <translation>Inverze krokového signálu</translation>
    </message>
    <message>
        <source>Axes whose step signal is inverted, one bit each (X 1, Y 2, Z 4), for drivers that step on the other edge.</source>
        <translation>Osy s obráceným krokovým signálem, každá jeden bit (X 1, Y 2, Z 4): pro budiče, které krokují na opačné hraně.</translation>
    </message>
    <message>
        <source>Direction invert</source>
        <translation>Inverze směru</translation>
    </message>
    <message>
        <source>Axes that move the other way, one bit each (X 1, Y 2, Z 4): the fix for an axis wired backwards.</source>
        <translation>Osy, které se pohybují opačně, každá jeden bit (X 1, Y 2, Z 4): náprava osy zapojené obráceně.</translation>
    </message>
    <message>
        <source>Invert step enable</source>
        <translation>Inverze povolení budičů</translation>
    </message>
    <message>
        <source>Inverts the drivers&apos; enable signal (takes effect after a reset).</source>
        <translation>Obrátí signál povolení budičů (platí po resetu).</translation>
    </message>
    <message>
        <source>Invert limit pins</source>
        <translation>Inverze koncových spínačů</translation>
    </message>
    <message>
        <source>Inverts every limit switch input: for switches that are closed until hit.</source>
        <translation>Obrátí všechny vstupy koncových spínačů: pro spínače sepnuté, dokud na ně osa nenarazí.</translation>
    </message>
    <message>
        <source>Invert probe pin</source>
        <translation>Inverze sondy</translation>
    </message>
    <message>
        <source>Inverts the probe input.</source>
        <translation>Obrátí vstup sondy.</translation>
    </message>
    <message>
        <source>Status report options</source>
        <translation>Obsah stavových hlášení</translation>
    </message>
    <message>
        <source>What a status report carries: value 1 the machine position (else the work position), value 2 the free buffer space.</source>
        <translation>Co nese stavové hlášení: hodnota 1 strojovou polohu (jinak pracovní), hodnota 2 volné místo ve vyrovnávacích pamětech.</translation>
    </message>
    <message>
        <source>Junction deviation</source>
        <translation>Odchylka v rozích</translation>
    </message>
    <message>
        <source>How fast the machine may go through a corner between two moves: smaller is slower and gentler.</source>
        <translation>Jak rychle smí stroj projet rohem mezi dvěma pohyby: menší je pomalejší a šetrnější.</translation>
    </message>
    <message>
        <source>Arc tolerance</source>
        <translation>Tolerance oblouků</translation>
    </message>
    <message>
        <source>How far the short lines GRBL draws an arc with may stray from the arc. Very small values cost speed.</source>
        <translation>Jak daleko se smějí krátké úsečky, kterými GRBL kreslí oblouk, od oblouku odchýlit. Velmi malé hodnoty stojí rychlost.</translation>
    </message>
    <message>
        <source>Report in inches</source>
        <translation>Hlášení v palcích</translation>
    </message>
    <message>
        <source>Positions and rates reported in inches instead of millimetres.</source>
        <translation>Polohy a rychlosti hlášené v palcích místo milimetrů.</translation>
    </message>
    <message>
        <source>Soft limits</source>
        <translation>Softwarové limity</translation>
    </message>
    <message>
        <source>Refuses, with an alarm, any motion past the maximum travel ($130…). Needs homing ($22=1).</source>
        <translation>Odmítne s alarmem každý pohyb za největší dráhu ($130…). Potřebuje najetí do výchozí polohy ($22=1).</translation>
    </message>
    <message>
        <source>Hard limits</source>
        <translation>Koncové spínače</translation>
    </message>
    <message>
        <source>Stops at once with an alarm when a limit switch is hit.</source>
        <translation>Zastaví okamžitě s alarmem, když osa narazí na koncový spínač.</translation>
    </message>
    <message>
        <source>Homing cycle</source>
        <translation>Najetí do výchozí polohy</translation>
    </message>
    <message>
        <source>Enables homing ($H). Needs a limit switch on every axis; the board then starts in alarm until homed.</source>
        <translation>Povolí najetí do výchozí polohy ($H). Potřebuje koncový spínač na každé ose; deska pak startuje v alarmu, dokud nenajede.</translation>
    </message>
    <message>
        <source>Homing direction invert</source>
        <translation>Inverze směru najíždění</translation>
    </message>
    <message>
        <source>Axes that look for their switch in the negative direction, one bit each (X 1, Y 2, Z 4).</source>
        <translation>Osy, které hledají svůj spínač v záporném směru, každá jeden bit (X 1, Y 2, Z 4).</translation>
    </message>
    <message>
        <source>Homing locate feed rate</source>
        <translation>Rychlost dohledání spínače</translation>
    </message>
    <message>
        <source>The slow speed at which homing finds the switch&apos;s exact place.</source>
        <translation>Pomalá rychlost, kterou najíždění najde přesné místo spínače.</translation>
    </message>
    <message>
        <source>Homing search seek rate</source>
        <translation>Rychlost hledání spínače</translation>
    </message>
    <message>
        <source>The fast speed at which homing first looks for the switch.</source>
        <translation>Rychlá rychlost, kterou najíždění nejdřív hledá spínač.</translation>
    </message>
    <message>
        <source>Homing switch debounce</source>
        <translation>Odskok spínače při najíždění</translation>
    </message>
    <message>
        <source>A pause between the phases of homing while the switch stops bouncing.</source>
        <translation>Pauza mezi fázemi najíždění, než spínač přestane zakmitávat.</translation>
    </message>
    <message>
        <source>Homing pull-off</source>
        <translation>Odjetí od spínače</translation>
    </message>
    <message>
        <source>How far homing backs off its switch. Homing fails if the switch is still pressed after it.</source>
        <translation>Jak daleko najíždění odjede od spínače. Selže, když je spínač potom stále sepnutý.</translation>
    </message>
    <message>
        <source>Maximum spindle speed</source>
        <translation>Největší otáčky vřetena</translation>
    </message>
    <message>
        <source>The S value that gives full PWM duty (on a servo pen plotter: the pen&apos;s full travel).</source>
        <translation>Hodnota S, která dá plnou střídu PWM (u plotru se servem: plný zdvih pera).</translation>
    </message>
    <message>
        <source>Minimum spindle speed</source>
        <translation>Nejmenší otáčky vřetena</translation>
    </message>
    <message>
        <source>The S value that gives the least PWM duty; below $30.</source>
        <translation>Hodnota S, která dá nejmenší střídu PWM; pod $30.</translation>
    </message>
    <message>
        <source>Laser mode</source>
        <translation>Laserový režim</translation>
    </message>
    <message>
        <source>Moves go on through changes of S without stopping, as a laser needs; a spindle would need time to change speed.</source>
        <translation>Pohyby pokračují přes změny S bez zastavení, jak potřebuje laser; vřeteno by potřebovalo čas na změnu otáček.</translation>
    </message>
    <message>
        <source>{0} resolution</source>
        <translation>{0} rozlišení</translation>
    </message>
    <message>
        <source>Steps the axis&apos;s motor makes for one millimetre of travel.</source>
        <translation>Kroky, které motor osy udělá na jeden milimetr dráhy.</translation>
    </message>
    <message>
        <source>{0} maximum rate</source>
        <translation>{0} největší rychlost</translation>
    </message>
    <message>
        <source>The axis&apos;s top speed; rapid moves (G0) run at it.</source>
        <translation>Nejvyšší rychlost osy; rychloposuvy (G0) jedou jí.</translation>
    </message>
    <message>
        <source>{0} acceleration</source>
        <translation>{0} zrychlení</translation>
    </message>
    <message>
        <source>How fast the axis may speed up and slow down, planned so that the motor loses no steps.</source>
        <translation>Jak rychle smí osa zrychlovat a brzdit, plánováno tak, aby motor neztratil kroky.</translation>
    </message>
    <message>
        <source>{0} maximum travel</source>
        <translation>{0} největší dráha</translation>
    </message>
    <message>
        <source>How far the axis can travel from its home switch: the space soft limits keep to, and how far homing searches.</source>
        <translation>Jak daleko může osa dojet od svého výchozího spínače: prostor, který hlídají softwarové limity, a kam až hledá najíždění.</translation>
    </message>
    <message>
        <source>$20 (soft limits) needs homing: $22=1</source>
        <extracomment>Every setting GRBL 1.1h lists in ``$$``, in its order.</extracomment>
        <translation>$20 (softwarové limity) potřebuje najetí do výchozí polohy: $22=1</translation>
    </message>
    <message>
        <source>$31 (minimum spindle speed) must be below $30</source>
        <translation>$31 (nejmenší otáčky vřetena) musí být pod $30</translation>
    </message>
    <message>
        <source>{0}: at most the mechanical travel, {1} mm</source>
        <translation>{0}: nejvýše mechanická dráha, {1} mm</translation>
    </message>
    <message>
        <source>{0} and {1}: {2} steps/s, more than GRBL steps ({3})</source>
        <translation>{0} a {1}: {2} kroků/s, víc, než GRBL zvládne ({3})</translation>
    </message>
</context>
<context>
    <name>HandZeroing</name>
    <message>
        <source>Not released: {0}</source>
        <extracomment>The motors were released for zeroing by hand and nothing was sent since.</extracomment>
        <translation>Neuvolněno: {0}</translation>
    </message>
    <message>
        <source>Motors released: turn the axes by hand to the zero, then Zero here</source>
        <translation>Motory uvolněny: otočte osy rukou do nuly, pak Nula zde</translation>
    </message>
    <message>
        <source>Not zeroed: release the motors first</source>
        <translation>Nevynulováno: nejprve uvolněte motory</translation>
    </message>
    <message>
        <source>Not zeroed: {0}</source>
        <translation>Nevynulováno: {0}</translation>
    </message>
    <message>
        <source>Zeroed by hand: X is the board radius, {0} mm</source>
        <translation>Vynulováno ručně: X je poloměr desky, {0} mm</translation>
    </message>
</context>
<context>
    <name>InfoPanel</name>
    <message>
        <source>Battery charge and voltage</source>
        <extracomment>The LED ring&apos;s colours, as drawn beside its state; blinking states say so in words. Status texts worth a colour; the rest stay in the normal text colour. The machine position, shown beside the work position while they differ.</extracomment>
        <translation>Nabití a napětí baterie</translation>
    </message>
    <message>
        <source>Link {0}</source>
        <translation>Spojení: {0}</translation>
    </message>
    <message>
        <source>Last known — the link is {0}</source>
        <translation>Poslední známá hodnota — spojení: {0}</translation>
    </message>
    <message>
        <source>battery —</source>
        <translation>baterie —</translation>
    </message>
    <message>
        <source>battery {0} %</source>
        <translation>baterie {0} %</translation>
    </message>
    <message>
        <source>board —</source>
        <translation>deska —</translation>
    </message>
    <message>
        <source>board {0} °C</source>
        <translation>deska {0} °C</translation>
    </message>
    <message>
        <source>LED ring: {0}</source>
        <translation>LED kruh: {0}</translation>
    </message>
    <message>
        <source>The stage&apos;s LED ring as its device flags say it is lit</source>
        <translation>LED kruh stolku, jak svítí podle jeho stavových příznaků</translation>
    </message>
    <message>
        <source>red</source>
        <translation>červená</translation>
    </message>
    <message>
        <source>red, blinking fast</source>
        <translation>červená, rychle bliká</translation>
    </message>
    <message>
        <source>green</source>
        <translation>zelená</translation>
    </message>
    <message>
        <source>blue, blinking slowly</source>
        <translation>modrá, pomalu bliká</translation>
    </message>
    <message>
        <source>blue</source>
        <translation>modrá</translation>
    </message>
    <message>
        <source>off</source>
        <translation>nesvítí</translation>
    </message>
    <message>
        <source>Charger connected</source>
        <translation>Nabíječka připojena</translation>
    </message>
    <message>
        <source>Battery low</source>
        <translation>Baterie téměř vybitá</translation>
    </message>
    <message>
        <source>Standby: the stage is asleep</source>
        <translation>Pohotovost: stolek spí</translation>
    </message>
    <message>
        <source>Pairing: waiting for a host</source>
        <translation>Párování: čeká na hostitele</translation>
    </message>
    <message>
        <source>Talking to this station</source>
        <translation>Komunikuje s touto stanicí</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Vypnuto</translation>
    </message>
    <message>
        <source>charger connected</source>
        <translation>připojena nabíječka</translation>
    </message>
    <message>
        <source>USB connected</source>
        <translation>připojeno USB</translation>
    </message>
    <message>
        <source>battery low</source>
        <translation>slabá baterie</translation>
    </message>
    <message>
        <source>machine {0}</source>
        <translation>stroj {0}</translation>
    </message>
    <message>
        <source>Machine position; the figure on the left is the work position (G92 work offset {0})</source>
        <translation>Poloha stroje; údaj vlevo je pracovní poloha (pracovní posunutí G92 {0})</translation>
    </message>
</context>
<context>
    <name>JobFile</name>
    <message>
        <source>{0}: {1} has no diameter: its {2} hole(s) are not drilled (give the tool a diameter in the file)</source>
        <extracomment>Diameters closer than this (mm) are the same bit. Tools whose holes are not drilled (no diameter). What the operator is told: each duplicate and each tool without a diameter.</extracomment>
        <translation>{0}: {1} nemá průměr: jeho otvory ({2}) se nevrtají (doplňte nástroji průměr v souboru)</translation>
    </message>
    <message>
        <source>{0}: {1} is {2:.2f} mm like {3}: its {4} hole(s) are drilled with {3}&apos;s bit, no change</source>
        <translation>{0}: {1} má {2:.2f} mm jako {3}: jeho otvory ({4}) se vrtají vrtákem {3}, bez výměny</translation>
    </message>
    <message>
        <source>no &apos;Units : 1/10000 Inch&apos; line: not an EAGLE .dri</source>
        <extracomment>The highest tool number a drill file may use (Excellon writes two or three digits). The most holes (slot ends counted) a drill file may ask for, repeats (``R…``) included: boards have tens to a few thousand holes; 50 000 (the benchmark&apos;s board) still checks in seconds, where a repeat count of nine digits made gerbonara build holes until memory ran out.</extracomment>
        <translation>chybí řádek „Units : 1/10000 Inch“: nejde o .dri z EAGLE</translation>
    </message>
    <message>
        <source>its drill file {0} is missing</source>
        <translation>chybí k němu vrtací soubor {0}</translation>
    </message>
    <message>
        <source>{0}… ({1} digits)</source>
        <translation>{0}… ({1} číslic)</translation>
    </message>
    <message>
        <source>tool number T{0} is above T{1}</source>
        <translation>číslo nástroje T{0} je nad T{1}</translation>
    </message>
    <message>
        <source>tool diameter {0} is not a number</source>
        <translation>průměr nástroje {0} není číslo</translation>
    </message>
    <message>
        <source>tool diameter of T{0:02d} is {1:g}: a drill must be wider than 0</source>
        <translation>průměr T{0:02d} je {1:g}: vrták musí mít průměr větší než 0</translation>
    </message>
    <message>
        <source>routed arcs (G02/G03) cannot be drilled</source>
        <translation>frézované oblouky (G02/G03) nelze vrtat</translation>
    </message>
    <message>
        <source>G85 slot without an end point: nothing to cut to</source>
        <translation>drážka G85 bez koncového bodu: není kam frézovat</translation>
    </message>
    <message>
        <source>no unit in the file; inch assumed, as the Excellon step is</source>
        <translation>soubor neuvádí jednotky; předpokládají se palce, stejně jako u kroku Excellonu</translation>
    </message>
    <message>
        <source>not an Excellon statement: {0}</source>
        <translation>nejde o příkaz Excellonu: {0}</translation>
    </message>
    <message>
        <source>unknown tool: {0} is not defined</source>
        <translation>neznámý nástroj: {0} není definován</translation>
    </message>
    <message>
        <source>integer coordinates, but the file gives no number format (metric)</source>
        <translation>celočíselné souřadnice, ale soubor neuvádí formát čísel (metrický)</translation>
    </message>
    <message>
        <source>the Excellon reader cannot read {0} ({1})</source>
        <translation>čtečka Excellonu nedokáže přečíst {0} ({1})</translation>
    </message>
    <message>
        <source>coordinates before any tool is selected: {0}</source>
        <translation>souřadnice před výběrem nástroje: {0}</translation>
    </message>
    <message>
        <source>coordinates before the header: {0}</source>
        <translation>souřadnice před hlavičkou: {0}</translation>
    </message>
    <message>
        <source>coordinates after the end of the program: {0}</source>
        <translation>souřadnice za koncem programu: {0}</translation>
    </message>
    <message>
        <source>a coordinate too large for a number</source>
        <translation>souřadnice je příliš velká</translation>
    </message>
    <message>
        <source>no holes in the file: nothing to drill</source>
        <translation>v souboru nejsou žádné otvory: není co vrtat</translation>
    </message>
    <message>
        <source>{0} of {1} is not in the tool list</source>
        <translation>{0} ze souboru {1} není v seznamu nástrojů</translation>
    </message>
    <message>
        <source>{0} is {1:.3f} mm here but {2:.3f} mm in {3}</source>
        <translation>{0} má zde {1:.3f} mm, ale v {3} {2:.3f} mm</translation>
    </message>
    <message>
        <source>{0} drills {1} holes here but {2} in {3}: the files do not belong together</source>
        <translation>{0} vrtá zde {1} otvorů, ale v {3} {2}: soubory k sobě nepatří</translation>
    </message>
    <message>
        <source> (also {0})</source>
        <extracomment>Duplicate tools and tools without a diameter, &quot;file:line: text&quot; (see bits.py).</extracomment>
        <translation> (i {0})</translation>
    </message>
    <message>
        <source>insert {0}, {1:.2f} mm, {2} hole{3}</source>
        <translation>vložte {0}, {1:.2f} mm, {2} otvor{3}</translation>
    </message>
    <message>
        <source>insert {0}, {1:.2f} mm, {2} holes{3}</source>
        <translation>vložte {0}, {1:.2f} mm, otvorů: {2}{3}</translation>
    </message>
    <message>
        <source>pen for {0}, {1:.2f} mm, {2} hole{3}</source>
        <translation>pero pro {0}, {1:.2f} mm, {2} otvor{3}</translation>
    </message>
    <message>
        <source>pen for {0}, {1:.2f} mm, {2} holes{3}</source>
        <translation>pero pro {0}, {1:.2f} mm, otvorů: {2}{3}</translation>
    </message>
    <message>
        <source>travel between holes: {0:.1f} mm in file order, {1:.1f} mm optimised ({2:.1f} mm saved)</source>
        <translation>pojezd mezi otvory: {0:.1f} mm v pořadí souboru, {1:.1f} mm po optimalizaci (ušetřeno {2:.1f} mm)</translation>
    </message>
    <message>
        <source>: warning: </source>
        <translation>: varování: </translation>
    </message>
    <message>
        <source>arc target invalid: an R arc needs distinct ends (error:33): {0}</source>
        <extracomment>Largest chord error of a flattened arc (mm, GRBL&apos;s $12) and the fewest segments one gets. The most chords one arc becomes; an arc needing more is refused. The most inner vertices all the arcs of one file become. GRBL&apos;s arc definition check: the end&apos;s radius may differ from the start&apos;s by this much… …and beyond it by at most 0.5 mm and 0.1 % of the radius (gcode.c).</extracomment>
        <translation>neplatný cíl oblouku: oblouk R potřebuje různé koncové body (error:33): {0}</translation>
    </message>
    <message>
        <source>arc radius error: R {0:g} mm is less than half the chord {1:g} mm (error:34): {2}</source>
        <translation>chyba poloměru oblouku: R {0:g} mm je menší než polovina tětivy {1:g} mm (error:34): {2}</translation>
    </message>
    <message>
        <source>arc without offsets: it needs I/J or R (error:35): {0}</source>
        <translation>oblouk bez středu: potřebuje I/J nebo R (error:35): {0}</translation>
    </message>
    <message>
        <source>arc coordinates too large to draw: {0}</source>
        <translation>souřadnice oblouku jsou příliš velké na vykreslení: {0}</translation>
    </message>
    <message>
        <source>arc end not on its circle: radius {0:.4g} mm at the start, {1:.4g} mm at the end (error:33): {2}</source>
        <translation>konec oblouku neleží na jeho kružnici: poloměr {0:.4g} mm na začátku, {1:.4g} mm na konci (error:33): {2}</translation>
    </message>
    <message>
        <source>arc too long: {0:.4g} m of radius {1:.4g} mm needs {2} chords at {3:g} mm (at most {4}); no machine&apos;s travel holds it</source>
        <translation>oblouk je příliš dlouhý: {0:.4g} m o poloměru {1:.4g} mm vyžaduje {2} úseček při {3:g} mm (nejvýše {4}); takový pojezd nemá žádný stroj</translation>
    </message>
    <message>
        <source>arcs too many: the file&apos;s arcs need more than {0:,} vertices at {1:g} mm</source>
        <translation>příliš mnoho oblouků: oblouky v souboru vyžadují víc než {0:,} vrcholů při {1:g} mm</translation>
    </message>
    <message>
        <source>more than 16 axes</source>
        <extracomment>Pen lines sent as the profile&apos;s own pen command.</extracomment>
        <translation>víc než 16 os</translation>
    </message>
    <message>
        <source>no G-code to send in the file</source>
        <translation>v souboru není žádný G-kód k odeslání</translation>
    </message>
    <message>
        <source>named parameters/expressions are not G-code this machine runs</source>
        <extracomment>Translated where it is used (a parameter line is refused in the operator&apos;s language).</extracomment>
        <translation>pojmenované parametry a výrazy nejsou G-kód, který tento stroj provádí</translation>
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
        <translation>překročena největší hodnota: T{0} nad T{1} (error:38)</translation>
    </message>
    <message>
        <source>negative value: {0} cannot be negative (error:4)</source>
        <translation>záporná hodnota: {0} nesmí být záporné (error:4)</translation>
    </message>
    <message>
        <source>modal group violation: two motion words (error:21): {0}</source>
        <translation>porušení modální skupiny: dva příkazy pohybu (error:21): {0}</translation>
    </message>
    <message>
        <source>invalid line number: N{0} above N{1} (error:27)</source>
        <translation>neplatné číslo řádku: N{0} nad N{1} (error:27)</translation>
    </message>
    <message>
        <source>M{0}: paused</source>
        <translation>M{0}: pozastaveno</translation>
    </message>
    <message>
        <source>{0} cannot execute {1}</source>
        <extracomment>A bare ``G92`` makes the current position the origin (the CoreXY plotter&apos;s firmware); GRBL refuses it (error:26). A G4 with P was read (its unit is worth a note where it is seconds). Inner arc vertices the file&apos;s arcs may still have (arcs.MAX_ARC_VERTICES in all). Lines whose operations depend on nothing but their text (pen commands, dwells): the pen state they set, their operations and the machine&apos;s objections. Lines refused at load (GRBL&apos;s errors, malformed text), in file order. Columns whose positions count from wherever the machine stands when the job starts (a G91 move or a G92 before the file set them): taken here as from 0.</extracomment>
        <translation>{0} neumí provést {1}</translation>
    </message>
    <message>
        <source>? not sent: the station asks for the status itself</source>
        <translation>? neodesláno: stanice se na stav ptá sama</translation>
    </message>
    <message>
        <source>{0} ({1}) is a real-time command, not a line of a job</source>
        <translation>{0} ({1}) je příkaz reálného času, ne řádek úlohy</translation>
    </message>
    <message>
        <source>arc without axis words (error:26): {0}</source>
        <translation>oblouk bez souřadnic os (error:26): {0}</translation>
    </message>
    <message>
        <source>feed rate undefined: {0} before any F sets one (error:22): {1}</source>
        <translation>posuv není zadán: {0} dřív, než ho nastaví F (error:22): {1}</translation>
    </message>
    <message>
        <source>{0} is not ASCII</source>
        <translation>{0} není ASCII</translation>
    </message>
    <message>
        <source>{0} characters; a line holds at most {1}</source>
        <translation>{0} znaků; řádek pojme nejvýše {1}</translation>
    </message>
    <message>
        <source>{0} has no {1} axis</source>
        <translation>{0} nemá osu {1}</translation>
    </message>
    <message>
        <source>not sent: {0} ({1})</source>
        <translation>neodesláno: {0} ({1})</translation>
    </message>
    <message>
        <source>{0} pen line sent as the {1}&apos;s {2}/{3}</source>
        <translation>řádky pera odeslány jako {2}/{3} stroje {1}: {0}</translation>
    </message>
    <message>
        <source>{0} pen lines sent as the {1}&apos;s {2}/{3}</source>
        <translation>řádky pera odeslány jako {2}/{3} stroje {1}: {0}</translation>
    </message>
    <message>
        <source>pen servo {0}: S{1:g} lowers the pen, S{2:g} lifts it</source>
        <translation>servo pera {0}: S{1:g} pero spouští, S{2:g} zvedá</translation>
    </message>
    <message>
        <source>Z heights are the pen: above 0 up, 0 or below down</source>
        <translation>výška Z je pero: nad 0 nahoře, 0 a níž dole</translation>
    </message>
    <message>
        <source>Z not sent on {0} line(s): Z is the {1}&apos;s pen and this file&apos;s Z never lifts it</source>
        <translation>Z neodesláno na řádcích: {0}; Z je pero stroje {1} a Z v tomto souboru ho nikdy nezvedá</translation>
    </message>
    <message>
        <source>{0} G21 line not sent: the machine works in mm</source>
        <translation>řádky G21 neodeslány: {0}; stroj pracuje v mm</translation>
    </message>
    <message>
        <source>{0} G21 lines not sent: the machine works in mm</source>
        <translation>řádky G21 neodeslány: {0}; stroj pracuje v mm</translation>
    </message>
    <message>
        <source>G4 P is seconds on the {0} (GRBL): {1} dwell(s) wait {2} in all; a file written for milliseconds (Marlin, Inkscape Unicorn) waits a thousand times too long here</source>
        <translation>G4 P jsou na stroji {0} (GRBL) sekundy: prodlevy ({1}) čekají celkem {2}; soubor psaný pro milisekundy (Marlin, Inkscape Unicorn) tu čeká tisíckrát déle</translation>
    </message>
    <message>
        <source>this plotter ignores F ({0} line(s) carry it): G0 and G1 run alike, the speed is set by M98 &lt;µs&gt; (the step interval, {1:g} µs at power-on)</source>
        <translation>tento plotr F nepoužívá (nese ho {0} řádků): G0 a G1 jedou stejně, rychlost nastavuje M98 &lt;µs&gt; (interval mezi kroky, po zapnutí {1:g} µs)</translation>
    </message>
    <message>
        <source>no pen commands: G0 moves are shown as travel, G1/G2/G3 as work</source>
        <translation>žádné příkazy pera: pohyby G0 se zobrazují jako přejezd, G1/G2/G3 jako práce</translation>
    </message>
    <message>
        <source> and {0} more</source>
        <translation> a dalších {0}</translation>
    </message>
    <message>
        <source>skipped 1 line: {0} (line {1})</source>
        <translation>přeskočen 1 řádek: {0} (řádek {1})</translation>
    </message>
    <message>
        <source>skipped {0} line(s): {1} (lines {2}{3})</source>
        <translation>přeskočeno řádků: {0}: {1} (řádky {2}{3})</translation>
    </message>
    <message>
        <source>could not split the file into lines</source>
        <extracomment>One record per line: group 1 is the G0/G1 digit of a plain move (a comment may follow), empty for any other line. Plain lines read in one call (regex, numpy): short enough that the window, waiting for the interpreter lock meanwhile, is not kept waiting long. FAST_LINE on the file&apos;s UTF-8 bytes (the pattern is ASCII: the same lines match).</extracomment>
        <translation>soubor nešlo rozdělit na řádky</translation>
    </message>
    <message>
        <source>could not read the coordinates</source>
        <translation>souřadnice nešlo přečíst</translation>
    </message>
    <message>
        <source>status query</source>
        <extracomment>The longest line a board takes, without its line end (docs/protocols.md §4: 80 bytes). A word whose number is written with an exponent (``X1e308``): G-code reads it as two words. ``M98 800`` / ``M99 90``: the CoreXY plotter&apos;s step interval and servo level (docs/protocols.md §4.5), the only codes a bare value (a number with no letter) follows. A bare value as a file may write it: unsigned, a digit first. Their names are translated where they are shown.</extracomment>
        <translation>dotaz na stav</translation>
    </message>
    <message>
        <source>feed hold</source>
        <translation>pozastavení posuvu</translation>
    </message>
    <message>
        <source>cycle start</source>
        <translation>start cyklu</translation>
    </message>
    <message>
        <source>soft reset</source>
        <translation>softwarový reset</translation>
    </message>
    <message>
        <source>malformed G-code at {0} in {1}</source>
        <extracomment>The cached tokenisations (per distinct line text) stop growing here: repeated lines (pen commands, dwells) are what the cache is for.</extracomment>
        <translation>chybný G-kód u {0} v {1}</translation>
    </message>
    <message>
        <source>continue when ready</source>
        <translation>pokračujte, až budete připraveni</translation>
    </message>
    <message>
        <source>expected {0} numbers, found {1}</source>
        <translation>očekáváno čísel: {0}, nalezeno: {1}</translation>
    </message>
    <message>
        <source>not a number in {0}</source>
        <translation>není číslo v {0}</translation>
    </message>
    <message>
        <source>not a finite number in {0}</source>
        <translation>není konečné číslo v {0}</translation>
    </message>
    <message>
        <source>no positions in the file</source>
        <translation>v souboru nejsou žádné polohy</translation>
    </message>
    <message>
        <source>turn beside it</source>
        <extracomment>The winder&apos;s axes: base angle (deg), tool radius (mm), tool along the drill axis (mm). The nail each operation serves (-1: none). The sequence entry each operation winds to (-1: drill phase). The axis each MOVE sets (0 A, 1 X, 2 Z; -1 for other operations) and its value. Index of the operator&apos;s WAIT between drilling and winding. Model seconds on the profile it was built for (None without a profile). The largest outer radius (each nail&apos;s own is its radius plus ``needle_out_mm``). The dwells at the holes&apos; bottoms (``G4`` operations) and how long each is. Operations read at a time by :meth:`StringArtProgram.column_after`. Entries computed at a time: the temporaries of a chunk stay a few megabytes however long the list (a whole 2-million-entry list at once took about 150 MB of them). Translated once per program (an operation is made each time it is read).</extracomment>
        <translation>natočit vedle něj</translation>
    </message>
    <message>
        <source>needle out</source>
        <translation>jehla ven</translation>
    </message>
    <message>
        <source>round the nail</source>
        <translation>kolem hřebíku</translation>
    </message>
    <message>
        <source>needle in</source>
        <translation>jehla dovnitř</translation>
    </message>
    <message>
        <source>nail {0} ({1}/{2}): {3}</source>
        <translation>hřebík {0} ({1}/{2}): {3}</translation>
    </message>
    <message>
        <source>a board of {0:g} cm radius leaves no room for the needle {1:g} mm inside the nails</source>
        <translation>deska o poloměru {0:g} cm nenechává místo pro jehlu {1:g} mm uvnitř hřebíků</translation>
    </message>
    <message>
        <source>drill phase: {0} nails</source>
        <translation>vrtání: hřebíků {0}</translation>
    </message>
    <message>
        <source>{0:g} mm above the board</source>
        <translation>{0:g} mm nad deskou</translation>
    </message>
    <message>
        <source>drill {0}</source>
        <translation>vrták {0}</translation>
    </message>
    <message>
        <source>drill nail {0}</source>
        <translation>vrtání pro hřebík {0}</translation>
    </message>
    <message>
        <source>{0}: turn the base</source>
        <translation>{0}: natočit základnu</translation>
    </message>
    <message>
        <source>{0}: tool to its radius</source>
        <translation>{0}: nástroj na jeho poloměr</translation>
    </message>
    <message>
        <source>{0}: drill</source>
        <translation>{0}: vrtat</translation>
    </message>
    <message>
        <source>{0}: at the bottom</source>
        <translation>{0}: na dně</translation>
    </message>
    <message>
        <source>{0}: back {1}</source>
        <translation>{0}: zpět {1}</translation>
    </message>
    <message>
        <source>back to nail 0</source>
        <translation>zpět k hřebíku 0</translation>
    </message>
    <message>
        <source>winding: {0} connections</source>
        <translation>navíjení: spojů {0}</translation>
    </message>
    <message>
        <source>drivers off while waiting</source>
        <translation>budiče vypnuty během čekání</translation>
    </message>
    <message>
        <source>Insert the nails, tie the thread to nail {0}</source>
        <translation>Vložte hřebíky, uvažte nit k hřebíku {0}</translation>
    </message>
    <message>
        <source>start at nail {0}</source>
        <translation>začátek u hřebíku {0}</translation>
    </message>
    <message>
        <source>{0}: needle out</source>
        <translation>{0}: jehla ven</translation>
    </message>
    <message>
        <source>{0}: turn</source>
        <translation>{0}: natočit</translation>
    </message>
    <message>
        <source>{0}: needle in</source>
        <translation>{0}: jehla dovnitř</translation>
    </message>
    <message>
        <source>{0}: turn back</source>
        <translation>{0}: natočit zpět</translation>
    </message>
    <message>
        <source>drill driver off while winding</source>
        <translation>budič vrtačky vypnut během navíjení</translation>
    </message>
    <message>
        <source>winding done: tie the thread off at nail {0}</source>
        <translation>navíjení hotovo: uvažte nit na hřebíku {0}</translation>
    </message>
    <message>
        <source>a string-art job needs the winder&apos;s axes A, X and Z (profile string-art); this machine has {0}</source>
        <translation>úloha string-art potřebuje osy navíječky A, X a Z (profil string-art); tento stroj má {0}</translation>
    </message>
    <message>
        <source>none</source>
        <translation>žádné</translation>
    </message>
    <message>
        <source>circle</source>
        <extracomment>The most nails a board may have (boards are wound with a few hundred). The most sides of a polygonal board. The largest board radius, in cm (no winder turns a board of 10 m). The most nail indices in a sequence. A nail index with more digits is out of range on any board (MAX_NAILS has five).</extracomment>
        <translation>kruhu</translation>
    </message>
    <message>
        <source>{0}-gon</source>
        <translation>{0}úhelníku</translation>
    </message>
    <message>
        <source>{0} nails on a {1} of {2:g} cm radius, {3} connections, thread {4:.1f} m</source>
        <extracomment>The line of each sequence entry in ``poradi_path`` (1-based; int32 for long lists). The line of each ``param.txt`` key (absent: supplied by the operator).</extracomment>
        <translation>hřebíků: {0} na {1} o poloměru {2:g} cm, spojů: {3}, nit {4:.1f} m</translation>
    </message>
    <message>
        <source>, about {0}</source>
        <translation>, asi {0}</translation>
    </message>
    <message>
        <source>a nail list without {0}: give the board (shape, at least {1} nails, radius) to load its {2} entries</source>
        <translation>seznam hřebíků bez {0}: zadejte desku (tvar, nejméně {1} hřebíků, poloměr), aby šlo načíst jeho položky ({2})</translation>
    </message>
    <message>
        <source>expected &apos;key = value&apos;, found {0}</source>
        <translation>očekáváno „klíč = hodnota“, nalezeno {0}</translation>
    </message>
    <message>
        <source>{0} given twice (first on line {1})</source>
        <translation>{0} zadáno dvakrát (poprvé na řádku {1})</translation>
    </message>
    <message>
        <source>{0} = {1} is not a number</source>
        <translation>{0} = {1} není číslo</translation>
    </message>
    <message>
        <source>{0} = {1} is too large</source>
        <translation>{0} = {1} je příliš velké</translation>
    </message>
    <message>
        <source>{0} = {1} is not a whole number</source>
        <translation>{0} = {1} není celé číslo</translation>
    </message>
    <message>
        <source>no &apos;{0} = …&apos; line (line 0: missing, not wrong)</source>
        <translation>chybí řádek „{0} = …“ (řádek 0: chybí, není chybný)</translation>
    </message>
    <message>
        <source>tvar = {0}: a polygon has at most {1} sides</source>
        <translation>tvar = {0}: mnohoúhelník má nejvýše {1} stran</translation>
    </message>
    <message>
        <source>tvar = {0}: the shape must be 0 (a circle) or 3 or more (a regular polygon)</source>
        <translation>tvar = {0}: tvar musí být 0 (kruh) nebo 3 a víc (pravidelný mnohoúhelník)</translation>
    </message>
    <message>
        <source>pocet_hrebiku = {0}: a board has at most {1} nails</source>
        <translation>pocet_hrebiku = {0}: deska má nejvýše {1} hřebíků</translation>
    </message>
    <message>
        <source>pocet_hrebiku = {0}: a board needs at least {1} nails</source>
        <translation>pocet_hrebiku = {0}: deska potřebuje nejméně {1} hřebíků</translation>
    </message>
    <message>
        <source>polomer_matrice = {0:g} cm: a board&apos;s radius is at most {1}</source>
        <translation>polomer_matrice = {0:g} cm: poloměr desky je nejvýše {1}</translation>
    </message>
    <message>
        <source>polomer_matrice = {0:g} cm: the nails sit {1:g} cm inside the edge, so the radius must be larger than {1:g} cm</source>
        <translation>polomer_matrice = {0:g} cm: hřebíky jsou {1:g} cm od okraje, poloměr proto musí být větší než {1:g} cm</translation>
    </message>
    <message>
        <source>number {0} of the file: {1} is not a whole number</source>
        <extracomment>The sequence as int64 (what numpy reads; the tuple is made from it). Values converted between numpy and Python at a time: one conversion of millions holds the interpreter lock throughout (a tenth of a second), and the GUI thread waits for it. Byte classes of a nail list: separators, digits, signs, anything else.</extracomment>
        <translation>číslo {0} v souboru: {1} není celé číslo</translation>
    </message>
    <message>
        <source>no nail indices in the file</source>
        <translation>v souboru nejsou žádná čísla hřebíků</translation>
    </message>
    <message>
        <source>the count of the file has {1} digits: out of range on any board (at most {2} nails, {3} entries)</source>
        <translation>počet v souboru má {1} číslic: mimo rozsah jakékoli desky (nejvýše {2} hřebíků, {3} položek)</translation>
    </message>
    <message>
        <source>number {0} of the file has {1} digits: out of range on any board (at most {2} nails, {3} entries)</source>
        <translation>číslo {0} v souboru má {1} číslic: mimo rozsah jakékoli desky (nejvýše {2} hřebíků, {3} položek)</translation>
    </message>
    <message>
        <source>more than {0} nail indices</source>
        <translation>víc než {0} čísel hřebíků</translation>
    </message>
    <message>
        <source>could not read the nail indices</source>
        <translation>čísla hřebíků nešlo přečíst</translation>
    </message>
    <message>
        <source>the count says {0} nail indices, but {1} follow</source>
        <translation>počet uvádí {0} čísel hřebíků, ale následuje {1}</translation>
    </message>
    <message>
        <source>fewer than two nails: nothing to wind</source>
        <translation>méně než dva hřebíky: není co navíjet</translation>
    </message>
    <message>
        <source> ({0} more out of range)</source>
        <translation> (mimo rozsah jsou ještě další: {0})</translation>
    </message>
    <message>
        <source>entry {0}: nail {1} is out of range 0…{2}{3}</source>
        <translation>položka {0}: hřebík {1} je mimo rozsah 0…{2}{3}</translation>
    </message>
    <message>
        <source>entries {0} and {1}: nail {2} twice in a row (a thread to itself)</source>
        <translation>položky {0} a {1}: hřebík {2} dvakrát za sebou (nit sama k sobě)</translation>
    </message>
    <message>
        <source>the board entered: {0}</source>
        <translation>zadaná deska: {0}</translation>
    </message>
    <message>
        <source>no {0} beside it (the nail order)</source>
        <translation>vedle něj chybí {0} (pořadí hřebíků)</translation>
    </message>
    <message>
        <source>which format? {0}: {1} (choose one: {2})</source>
        <extracomment>Drill files: prompt the bits smallest first instead of in the file&apos;s tool order. Drill files: every hole with the one bit in the spindle, no bit-change prompt (the original drill&apos;s way; a profile&apos;s ``[drill] one_bit``, FIDELITY S2-40). Drill files: what the teacher&apos;s Excellon step makes of their coordinates (its ratio to 1/10000 inch), and per axis name the ratio of the teacher&apos;s microsteps a mm to the profile&apos;s, every job&apos;s (FIDELITY S2-42). 1: the profile&apos;s constants. G-code: pen lines of another flavour are sent as the machine&apos;s own pen commands. G-code: lines the machine cannot execute become comments instead of refusing the job. G-code: the machine&apos;s repertoire and pen conventions (None: a GRBL board). G-code: the machine&apos;s name in refusals (&quot;the CoreXY pen plotter cannot execute M18&quot;). String-art nail lists without a param.txt: the board the operator gave (NeedsNailCount). The job type&apos;s key when the operator chose it (an ambiguous file); None: detected. Reads ``path`` for a machine with these axis names; raises JobFileError with file:line. Whether the first few kilobytes of a file look like this loader&apos;s job type. The short name ``--format`` takes and a chosen format is stored as.</extracomment>
        <translation>který formát? {0}: {1} (vyberte jeden: {2})</translation>
    </message>
    <message>
        <source> or </source>
        <translation> nebo </translation>
    </message>
    <message>
        <source>the file is empty</source>
        <extracomment>Lower-case extension (with the dot) → loader; the dock&apos;s first choice. Every registered job type in registration order: file-dialog filters and sniffing.</extracomment>
        <translation>soubor je prázdný</translation>
    </message>
    <message>
        <source>its content fits several job types</source>
        <translation>obsah odpovídá několika typům úloh</translation>
    </message>
    <message>
        <source>its content fits no {0} job type</source>
        <translation>obsah neodpovídá žádnému typu úlohy {0}</translation>
    </message>
    <message>
        <source>not a job file this station knows (unknown type)</source>
        <translation>nejde o soubor úlohy, který stanice zná (neznámý typ)</translation>
    </message>
    <message>
        <source>teaching: microsteps a mm changed, the job lands x {0} of its size</source>
        <translation>výuka: mikrokroky na mm změněny, úloha dopadne v {0} násobku své velikosti</translation>
    </message>
    <message>
        <source>a drill job needs a machine with X and Y axes</source>
        <translation>vrtací úloha potřebuje stroj s osami X a Y</translation>
    </message>
    <message>
        <source>teaching: read with an Excellon step of {0:g} inch (coordinates x {1:g})</source>
        <translation>výuka: čteno s krokem Excellon {0:g} palce (souřadnice × {1:g})</translation>
    </message>
    <message>
        <source>a folder</source>
        <extracomment>How much of a file the format sniffers see.</extracomment>
        <translation>složka</translation>
    </message>
    <message>
        <source>a named pipe</source>
        <translation>pojmenovaná roura</translation>
    </message>
    <message>
        <source>a device</source>
        <translation>zařízení</translation>
    </message>
    <message>
        <source>a block device</source>
        <translation>blokové zařízení</translation>
    </message>
    <message>
        <source>a socket</source>
        <translation>soket</translation>
    </message>
    <message>
        <source>not a regular file</source>
        <translation>není běžný soubor</translation>
    </message>
    <message>
        <source>too large: {0}; job files are read up to {1}</source>
        <translation>příliš velký: {0}; soubory úloh se čtou do {1}</translation>
    </message>
    <message>
        <source>too large: over {0}; job files are read up to that</source>
        <translation>příliš velký: přes {0}; soubory úloh se čtou jen do této velikosti</translation>
    </message>
    <message>
        <source>cannot read: {0}</source>
        <translation>nelze číst: {0}</translation>
    </message>
    <message>
        <source>cannot read: {0}, not a job file</source>
        <translation>nelze číst: {0}, ne soubor úlohy</translation>
    </message>
    <message>
        <source>UTF-16 text (little-endian byte-order mark): save it as UTF-8 or ASCII</source>
        <translation>text v UTF-16 (značka pořadí bajtů little-endian): uložte ho jako UTF-8 nebo ASCII</translation>
    </message>
    <message>
        <source>UTF-16 text (big-endian byte-order mark): save it as UTF-8 or ASCII</source>
        <translation>text v UTF-16 (značka pořadí bajtů big-endian): uložte ho jako UTF-8 nebo ASCII</translation>
    </message>
    <message>
        <source>UTF-16 text (every other byte is zero): save it as UTF-8 or ASCII</source>
        <translation>text v UTF-16 (každý druhý bajt je nula): uložte ho jako UTF-8 nebo ASCII</translation>
    </message>
    <message>
        <source>binary data (a zero byte at offset {0}): not a job file</source>
        <translation>binární data (nulový bajt na pozici {0}): nejde o soubor úlohy</translation>
    </message>
    <message>
        <source>not UTF-8 text (byte 0x{0:02x})</source>
        <translation>nejde o text v UTF-8 (bajt 0x{0:02x})</translation>
    </message>
    <message>
        <source>move to {0}</source>
        <extracomment>G-code text a G-code machine is sent as written (G-code files); empty: the dialect renders the operation from its kind and target.</extracomment>
        <translation>najet na {0}</translation>
    </message>
    <message>
        <source>line {0}: {1} — {2}</source>
        <translation>řádek {0}: {1} — {2}</translation>
    </message>
    <message>
        <source>{0}: {1} — {2} {3:g} is outside {4:g}…{5:g}</source>
        <translation>{0}: {1} — {2} {3:g} je mimo meze pojezdu {4:g}…{5:g}</translation>
    </message>
    <message>
        <source>G92 without axis words (error:26): {0}</source>
        <translation>G92 bez souřadnic os (error:26): {0}</translation>
    </message>
    <message>
        <source>repeat {0} asks for {1} holes; a drill file may have at most {2}</source>
        <translation>opakování {0} žádá {1} otvorů; vrtací soubor smí mít nejvýše {2}</translation>
    </message>
    <message>
        <source>more than {0} holes by this line; a drill file may have at most {0}</source>
        <translation>po tomto řádku více než {0} otvorů; vrtací soubor smí mít nejvýše {0}</translation>
    </message>
    <message>
        <source>a coordinate is not a number: {0}</source>
        <translation>souřadnice není číslo: {0}</translation>
    </message>
    <message>
        <source>{0} is not a G-code number (G-code has no exponent): it reads as {1} and {2}, and {3} has no {4} axis</source>
        <translation>{0} není číslo G-kódu (G-kód nezná exponent): čte se jako {1} a {2} a {3} nemá osu {4}</translation>
    </message>
    <message>
        <source>{0}: {1} — {2} {3:g}: the machine has no {2} axis</source>
        <extracomment>What the loader wants the operator to know (e.g. the travel its ordering saved). Axes the job moves relative to wherever the machine stands when it starts (a G-code file&apos;s G91 or G92 before it set them); its positions on them are as if that were 0, so the runner starts it only from there. What :meth:`preview_path` gives: &quot;axes&quot;, the two axes asked for as they are (the preview projects them on a polar machine), or &quot;board&quot;, the work&apos;s own plane in mm whatever the axes (a job that knows its geometry projects itself, and better).</extracomment>
        <translation>{0}: {1} — {2} {3:g}: stroj nemá osu {2}</translation>
    </message>
    <message>
        <source>change to pen T{0}</source>
        <extracomment>``M6``, ``M06 T2``, ``T2 M6``, ``m6t02``: the change, with its tool number before or after. The highest tool number GRBL takes (its T is a byte), as the parser refuses above it.</extracomment>
        <translation>vyměňte pero za T{0}</translation>
    </message>
    <message>
        <source>change the pen</source>
        <translation>vyměňte pero</translation>
    </message>
</context>
<context>
    <name>JobPreview</name>
    <message>
        <source>work</source>
        <extracomment>A click this many pixels from a hole picks it as a reference. Degrees per drawn step of a projected turn: an arc, not a chord, within a pixel or so. At most this many steps per move, so a move spinning the base many turns stays cheap. A path with more points than this is drawn without a dot on each. Points of the drawn reach circle. Runner states in which a job is under way: the machine is the job&apos;s, not the mouse&apos;s.</extracomment>
        <translation>práce</translation>
    </message>
    <message>
        <source>travel</source>
        <translation>přejezd</translation>
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
        <translation>meze pojezdu</translation>
    </message>
    <message>
        <source>Move the machine?</source>
        <translation>Pohnout strojem?</translation>
    </message>
    <message>
        <source>Drag pans, the wheel zooms, Fit shows it all; a click (not a drag) within the tool&apos;s reach turns the base and moves the tool there after you confirm</source>
        <translation>Tažením posunete pohled, kolečkem zvětšíte, Celé ukáže vše; kliknutí (ne tažení) v dosahu nástroje po potvrzení natočí základnu a najede tam nástrojem</translation>
    </message>
    <message>
        <source>Drag pans, the wheel zooms, Fit shows it all; a click (not a drag) inside the travel limits moves the machine there after you confirm</source>
        <translation>Tažením posunete pohled, kolečkem zvětšíte, Celé ukáže vše; kliknutí (ne tažení) uvnitř mezí pojezdu po potvrzení najede strojem na to místo</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>Celé</translation>
    </message>
    <message>
        <source>Show the whole job (without a job, the tool&apos;s reach)</source>
        <translation>Zobrazit celou úlohu (bez úlohy dosah nástroje)</translation>
    </message>
    <message>
        <source>Show the whole job and the machine&apos;s travel</source>
        <translation>Zobrazit celou úlohu a rozsah pojezdu stroje</translation>
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
        <translation>probíhá úloha</translation>
    </message>
    <message>
        <source>motion is locked: {0}</source>
        <translation>pohyb je zablokován: {0}</translation>
    </message>
    <message>
        <source>not connected</source>
        <translation>nepřipojeno</translation>
    </message>
    <message>
        <source>Click-to-move refused ({0}): {1}</source>
        <translation>Najetí kliknutím odmítnuto ({0}): {1}</translation>
    </message>
    <message>
        <source>{0} {1} is outside {2}…{3}</source>
        <translation>{0} {1} je mimo {2}…{3}</translation>
    </message>
    <message>
        <source>Click-to-move refused: {0} (soft limits)</source>
        <translation>Najetí kliknutím odmítnuto: {0} (softwarové limity)</translation>
    </message>
    <message>
        <source>Move to {0} {1}?</source>
        <translation>Najet na {0} {1}?</translation>
    </message>
    <message>
        <source>Click-to-move cancelled</source>
        <translation>Najetí kliknutím zrušeno</translation>
    </message>
    <message>
        <source>The machine refused the move to {0}</source>
        <translation>Stroj odmítl najet na {0}</translation>
    </message>
    <message>
        <source>Moving to {0}</source>
        <translation>Najíždím na {0}</translation>
    </message>
    <message>
        <source>Click-to-move refused: {0} {1} from the centre is beyond {2}&apos;s travel 0…{3} (the reach)</source>
        <translation>Najetí kliknutím odmítnuto: {0} {1} od středu je mimo pojezd osy {2} 0…{3} (dosah)</translation>
    </message>
    <message>
        <source>Turn {0} by {1}° to {2} {3}, then move {4} to {5} {6}?</source>
        <translation>Natočit {0} o {1}° na {2} {3} a pak najet osou {4} na {5} {6}?</translation>
    </message>
    <message>
        <source>Click a hole in the preview for reference {0}</source>
        <translation>Klikněte v náhledu na otvor pro referenční bod {0}</translation>
    </message>
    <message>
        <source>No hole there: click on a hole, or press Pick again to stop</source>
        <translation>Tady žádný otvor není: klikněte na otvor, nebo výběr ukončete dalším stiskem Vybrat</translation>
    </message>
    <message>
        <source>Hole {0} is reference {1}</source>
        <translation>Otvor {0} je referenční bod {1}</translation>
    </message>
    <message>
        <source>Click-to-move is off: {0}</source>
        <translation>Najetí kliknutím je vypnuto: {0}</translation>
    </message>
    <message>
        <source>Click a point within the tool&apos;s reach to move there (after confirming)</source>
        <translation>Klikněte na bod v dosahu nástroje a (po potvrzení) na něj najedete</translation>
    </message>
    <message>
        <source>Click a point inside the travel to move there (after confirming)</source>
        <translation>Klikněte na bod uvnitř pojezdu a (po potvrzení) na něj najedete</translation>
    </message>
    <message>
        <source>Preview: the {connections} connections are drawn merged, each of the {chords} different chords once, as dark as its windings make it</source>
        <extracomment>The thread&apos;s opacity (of 255): low, so that where threads cross the colour deepens. A merged thread&apos;s bands (see the module of the thread geometry), all and wound. The whole job&apos;s bands as one image painted on the loading thread, shown instead of ``thread_bands`` while the view is at the scale it was painted for. What the preview says when it draws the thread merged (&quot;&quot; when exact).</extracomment>
        <translation>Náhled: {connections} spojení je vykresleno sloučeně, každá z {chords} různých tětiv jednou, tím tmavší, čím víckrát je navinuta</translation>
    </message>
</context>
<context>
    <name>JobRunner</name>
    <message>
        <source>Stop the running job before loading another</source>
        <extracomment>Operations the machine reported as run, and the total. Equal to ``done`` where one operation is sent at a time; behind it on G-code, whose planner holds answered lines. Only the operator can tell whether an operation ran: question, &quot;again&quot; and &quot;done&quot; labels. Only the operator can say where an interrupted job goes on: a ResumeChoice. The station the job runs on (its profile, so its dialect, is kept for life). Operations done and executed, the estimate, the elapsed, running and waiting times and the time left; it emits the progress and ETA signals above. What the jog lock says while this runner&apos;s program is under way (a macro&apos;s runner says its own, so that neither kind of runner starts while the other&apos;s runs).</extracomment>
        <translation>Před načtením další úlohy zastavte tu běžící</translation>
    </message>
    <message>
        <source>Job {0} refused, {1} operation(s) cannot be run:
{2}</source>
        <translation>Úloha {0} odmítnuta, nelze provést operací: {1}
{2}</translation>
    </message>
    <message>
        <source>Job {0} was interrupted: {1} of {2} operations done; resume from {3} or discard the checkpoint</source>
        <translation>Úloha {0} byla přerušena: hotovo {1} z {2} operací; pokračujte od {3}, nebo kontrolní bod zahoďte</translation>
    </message>
    <message>
        <source>Resume from the checkpoint or discard it first</source>
        <translation>Nejdřív pokračujte od kontrolního bodu, nebo ho zahoďte</translation>
    </message>
    <message>
        <source>Job {0} not started from {1}: {2}</source>
        <translation>Úloha {0} nespuštěna od {1}: {2}</translation>
    </message>
    <message>
        <source>Answer the question about the interrupted operation first</source>
        <translation>Nejdřív odpovězte na otázku k přerušené operaci</translation>
    </message>
    <message>
        <source>Choose the line to resume from first</source>
        <translation>Nejdřív zvolte řádek, od kterého pokračovat</translation>
    </message>
    <message>
        <source>Job aborted after {0} of {1} operations</source>
        <translation>Úloha přerušena po {0} z {1} operací</translation>
    </message>
    <message>
        <source>Checkpoint discarded; the job starts from the beginning</source>
        <translation>Kontrolní bod zahozen; úloha začne od začátku</translation>
    </message>
    <message>
        <source>Job failed at {0}: {1}</source>
        <extracomment>The run stops after the operation under way (Step). A pause was asked for while an operation was under way (PAUSING). The operation the operator is asked about. Where to go on, for the operator to pick. Paused until the operator acts (an alarm, a board that restarted): nothing resumes it on its own (the scripting API ends the job instead). Paused because the link went, and nothing else has happened to the job since.</extracomment>
        <translation>Úloha selhala na {0}: {1}</translation>
    </message>
    <message>
        <source>Job paused at {0}: link {1}; resume once the machine is back</source>
        <translation>Úloha pozastavena na {0}: spojení {1}; pokračujte, až bude stroj zpět</translation>
    </message>
    <message>
        <source>Job paused: link {0}; resume once the machine is back</source>
        <translation>Úloha pozastavena: spojení {0}; pokračujte, až bude stroj zpět</translation>
    </message>
    <message>
        <source>Job {0} done: {1} operations in {2} s</source>
        <translation>Úloha {0} dokončena: operací {1} za {2} s</translation>
    </message>
    <message>
        <source>, of which {0} s waiting for you</source>
        <translation>, z toho {0} s čekání na vás</translation>
    </message>
    <message>
        <source>Job {0} not started: it moves {1} relative to where the machine stands (G91 or G92 before any absolute move), and was checked from 0; the machine is at {2}. Home it or move it to 0 first.</source>
        <translation>Úloha {0} nespuštěna: pohybuje {1} relativně k místu, kde stroj stojí (G91 nebo G92 před prvním absolutním pohybem), a byla zkontrolována od 0; stroj je na {2}. Nejprve proveďte referenční jízdu nebo ho přesuňte na 0.</translation>
    </message>
    <message>
        <source>not connected</source>
        <translation>nepřipojeno</translation>
    </message>
    <message>
        <source>Cannot run the job: {0}</source>
        <translation>Úlohu nelze spustit: {0}</translation>
    </message>
    <message>
        <source>a job is under way — abort it or let it finish</source>
        <extracomment>Refused operations listed in the message (the dock&apos;s list holds them all). How far from 0 (mm or degrees) a job that counts from its start may start.</extracomment>
        <translation>probíhá úloha — přerušte ji, nebo ji nechte doběhnout</translation>
    </message>
    <message>
        <source>The machine answers again, but {0}: the job stays paused. Check the machine, then Resume</source>
        <translation>Stroj opět odpovídá, ale {0}: úloha zůstává pozastavená. Zkontrolujte stroj a pak dejte Pokračovat</translation>
    </message>
    <message>
        <source>The machine answers again, its state intact: the job goes on</source>
        <translation>Stroj opět odpovídá a jeho stav je neporušený: úloha pokračuje</translation>
    </message>
    <message>
        <source>{0} is not supported on {1}</source>
        <translation>{0}: stroj {1} to nepodporuje</translation>
    </message>
    <message>
        <source>{0} cannot drill</source>
        <translation>{0} neumí vrtat</translation>
    </message>
    <message>
        <source>{0} drills only with explicit moves: G-code has no drill cycle</source>
        <translation>{0} vrtá jen výslovnými pohyby: G-code nemá vrtací cyklus</translation>
    </message>
    <message>
        <source>{0} has no pen</source>
        <translation>{0} nemá pero</translation>
    </message>
    <message>
        <source>{0} does not take G-code</source>
        <translation>{0} nepřijímá G-kód</translation>
    </message>
    <message>
        <source>{0}: a drill cycle drills where the tool stands; start at op {1}, the move to its hole</source>
        <extracomment>Link states in which nothing can be sent. Whether G-code lines (``OpKind.GCODE``) can be sent as they are.</extracomment>
        <translation>{0}: vrtací cyklus vrtá tam, kde nástroj stojí; začněte od op. {1}, najetí na jeho otvor</translation>
    </message>
    <message>
        <source>the drill is busy with another command</source>
        <translation>vrtačka je zaneprázdněna jiným příkazem</translation>
    </message>
    <message>
        <source>the drill refused it</source>
        <translation>vrtačka jej odmítla</translation>
    </message>
    <message>
        <source>the drill refused to home</source>
        <translation>vrtačka odmítla referenční jízdu</translation>
    </message>
    <message>
        <source>The drill cannot report whether it has homed, and the station has not seen it home since this link opened: homing first (N)</source>
        <translation>Vrtačka neumí ohlásit, zda prošla referenční jízdou, a stanice ji od otevření spojení referenční jízdu dělat neviděla: nejprve referenční jízda (N)</translation>
    </message>
    <message>
        <source>Parking at {0}</source>
        <translation>Parkování na {0}</translation>
    </message>
    <message>
        <source>Drill cycle at {0} was received by the machine, which finishes it on its own: counted as done</source>
        <translation>Vrtací cyklus na {0} stroj přijal a dokončí jej sám: počítá se jako hotový</translation>
    </message>
    <message>
        <source>the drill refused {0}</source>
        <translation>vrtačka odmítla {0}</translation>
    </message>
    <message>
        <source>Not parked: the drill refused {0}</source>
        <translation>Nezaparkováno: vrtačka odmítla {0}</translation>
    </message>
    <message>
        <source>the move was refused</source>
        <extracomment>Position echoes per moved axis, counted from a resume, before the machine&apos;s state is believed: more than a killed station can leave unread in a serial buffer.
----------
Station-clock seconds the unit has to show it started a move, or to say where it stands. Per axis of the operation: mm and station-clock time of its last report since the move (or the question) went out. Station-clock time the unit was asked where it stands because it fell silent short of the end: its answer, not the silence, says whether it stopped short. The last position each axis reported. A report is judged as it is decoded, before the session folds it into the model, so the model lags by the report under judgement.</extracomment>
        <translation>pohyb byl odmítnut</translation>
    </message>
    <message>
        <source>Checking whether {0} ({1}) was completed…</source>
        <translation>Ověřuje se, zda byla operace {0} ({1}) dokončena…</translation>
    </message>
    <message>
        <source>Operation at {0} was already complete</source>
        <translation>Operace na {0} už byla dokončena</translation>
    </message>
    <message>
        <source>{0} hit an end switch at {1} mm</source>
        <translation>{0} narazila na koncový spínač na {1} mm</translation>
    </message>
    <message>
        <source>Asking the unit where it stands ({0}, {1})…</source>
        <translation>Dotaz na polohu jednotky ({0}, {1})…</translation>
    </message>
    <message>
        <source>Starting at {0}: the machine goes there with the pen up, set as the file had it ({1})</source>
        <extracomment>Lines that may change the modal state this module follows (a literal-ish search over the text before the start; each hit is then read word by word). Motion words, and the codes they are. Words that make the position at the start unknown to the station&apos;s model. File offsets smaller than this (mm) are none. Operations after the start looked at for the move that needs the arc&apos;s word. Where the machine stands (program coordinates, mm), and whether the pen is down. The motion mode in force (``G0``…``G3``), None when the file set none yet. The feed in force, in the file&apos;s units per minute at the start (None: never set). The file&apos;s own G92 offset per axis (mm), as :func:`file_offset` gives it. The last operator prompt before the start (a pen or bit change), if any. The operation that gets the arc&apos;s motion word in front (see the module doc). The program is a G-code file whose own modal state is rebuilt (else only the position and the pen, as a resume does: its lines carry their own words).</extracomment>
        <translation>Začíná se od {0}: stroj tam najede se zvednutým perem, nastavený tak, jak ho tam měl soubor ({1})</translation>
    </message>
    <message>
        <source>; the file&apos;s last prompt before it was: {0}</source>
        <translation>; poslední výzva souboru před tímto místem byla: {0}</translation>
    </message>
    <message>
        <source>this job does not run in the order of its file&apos;s lines: start from an operation number instead</source>
        <translation>tato úloha neběží v pořadí řádků svého souboru: začněte raději od čísla operace</translation>
    </message>
    <message>
        <source>lines count from 1</source>
        <translation>řádky se číslují od 1</translation>
    </message>
    <message>
        <source>beyond the end: nothing runs after line {0}</source>
        <translation>za koncem: po řádku {0} se už nic neprovádí</translation>
    </message>
    <message>
        <source>the job has operations 1 to {0}</source>
        <translation>úloha má operace 1 až {0}</translation>
    </message>
    <message>
        <source>{0} before the start changes where the file&apos;s coordinates are, which the station does not follow: start before this line</source>
        <translation>{0} před začátkem mění, kde jsou souřadnice souboru, a to stanice nesleduje: začněte před tímto řádkem</translation>
    </message>
</context>
<context>
    <name>JobsDock</name>
    <message>
        <source>Which kind of job?</source>
        <extracomment>A refused file&apos;s further refused lines listed under the first one. Asks which job type an ambiguous file is; the chosen type&apos;s key, None when cancelled.</extracomment>
        <translation>Jaký druh úlohy?</translation>
    </message>
    <message>
        <source>{0}: the name and the content do not tell.
Read it as:</source>
        <translation>{0}: z názvu ani obsahu to nepoznám.
Načíst jako:</translation>
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
        <translation>Právě prováděná operace a řádek, ze kterého pochází</translation>
    </message>
    <message>
        <source>Messages about the job appear here</source>
        <translation>Zde se objeví zprávy o úloze</translation>
    </message>
    <message>
        <source>Draw holes with the pen</source>
        <extracomment>An option changed (or the drill&apos;s timing, which the estimate reads): read the file again.</extracomment>
        <translation>Otvory kreslit perem</translation>
    </message>
    <message>
        <source>Drill files: instead of drilling, the pen goes down (K) at each bit&apos;s first hole, draws along the following holes, X then Y, and comes up (Z) after the last, as the original tool drew</source>
        <translation>Vrtací soubory: místo vrtání sjede pero (K) na první otvor každého vrtáku, kreslí podél dalších otvorů, nejdřív X, pak Y, a za posledním se zvedne (Z), jak kreslil původní program</translation>
    </message>
    <message>
        <source>Crosses at the holes</source>
        <translation>Křížky na otvorech</translation>
    </message>
    <message>
        <source>Drawn drill files: a pen cross the size of each hole instead of one line along the holes</source>
        <translation>Kreslené vrtací soubory: perem křížek velikosti každého otvoru místo jedné čáry podél otvorů</translation>
    </message>
    <message>
        <source>Smallest bit first</source>
        <translation>Nejmenší vrták první</translation>
    </message>
    <message>
        <source>Drill files: the bit changes ordered from the smallest drill to the largest</source>
        <translation>Vrtací soubory: výměny vrtáků od nejmenšího po největší</translation>
    </message>
    <message>
        <source>1/{0} inch</source>
        <translation>1/{0} palce</translation>
    </message>
    <message>
        <source>Excellon step: the unit of bare integer coordinates</source>
        <translation>Krok Excellon: jednotka celočíselných souřadnic bez formátu</translation>
    </message>
    <message>
        <source>Excellon step</source>
        <translation>Krok Excellon</translation>
    </message>
    <message>
        <source>Use this machine&apos;s pen commands</source>
        <translation>Použít příkazy pera tohoto stroje</translation>
    </message>
    <message>
        <source>G-code: M300/M280 servo lines, Z pen heights, M3/M5 are sent as this machine&apos;s own pen-up / pen-down commands</source>
        <translation>G-kód: řádky serva M300/M280, výšky pera v Z a M3/M5 se posílají jako vlastní příkazy tohoto stroje pro zvednutí / spuštění pera</translation>
    </message>
    <message>
        <source>Skip lines it cannot run</source>
        <translation>Přeskočit neproveditelné řádky</translation>
    </message>
    <message>
        <source>G-code: lines this machine cannot execute (e.g. M18) are listed and left out instead of refusing the job</source>
        <translation>G-kód: řádky, které tento stroj neumí provést (např. M18), se vypíší a vynechají, místo aby byla úloha odmítnuta</translation>
    </message>
    <message>
        <source>Open…</source>
        <translation>Otevřít…</translation>
    </message>
    <message>
        <source>Open a job file (point list; the type is told by its content)</source>
        <translation>Otevřít soubor úlohy (seznam bodů; typ se pozná podle obsahu)</translation>
    </message>
    <message>
        <source>Export…</source>
        <translation>Exportovat…</translation>
    </message>
    <message>
        <source>Write the loaded job out: G-code, or a string-art job&apos;s SD-card files</source>
        <translation>Zapsat načtenou úlohu: G-kód nebo soubory pro SD kartu u string artu</translation>
    </message>
    <message>
        <source>From photo…</source>
        <extracomment>The &quot;From photo…&quot; dialog while it is open.</extracomment>
        <translation>Z fotografie…</translation>
    </message>
    <message>
        <source>String art from a photo: make a nail sequence, see it, load it as a job</source>
        <translation>String art z fotografie: vytvořit pořadí hřebíků, prohlédnout ho a načíst jako úlohu</translation>
    </message>
    <message>
        <source>no job loaded</source>
        <translation>žádná úloha nenačtena</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Spustit</translation>
    </message>
    <message>
        <source>Run the job from the start</source>
        <translation>Spustit úlohu od začátku</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pozastavit</translation>
    </message>
    <message>
        <source>Pause after the operation under way finishes</source>
        <translation>Pozastavit po dokončení probíhající operace</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Pokračovat</translation>
    </message>
    <message>
        <source>Go on from where the job paused</source>
        <translation>Pokračovat tam, kde se úloha pozastavila</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Krok</translation>
    </message>
    <message>
        <source>Execute the next operation only, then pause</source>
        <translation>Provést jen další operaci a pozastavit</translation>
    </message>
    <message>
        <source>Abort</source>
        <translation>Přerušit</translation>
    </message>
    <message>
        <source>Stop the machine now and end the job</source>
        <translation>Okamžitě zastavit stroj a ukončit úlohu</translation>
    </message>
    <message>
        <source>Time since the job started, prompts and pauses included; of it, how long the machine waited for you</source>
        <translation>Čas od spuštění úlohy včetně výzev a pauz; z toho, jak dlouho stroj čekal na vás</translation>
    </message>
    <message>
        <source>Go on after the last operation the machine completed; none is repeated</source>
        <translation>Pokračovat za poslední operací, kterou stroj dokončil; nic se neopakuje</translation>
    </message>
    <message>
        <source>Discard</source>
        <translation>Zahodit</translation>
    </message>
    <message>
        <source>Forget the interrupted run; Run then starts from the first operation</source>
        <translation>Zapomenout přerušený běh; Spustit pak začne první operací</translation>
    </message>
    <message>
        <source>Continue</source>
        <translation>Pokračovat</translation>
    </message>
    <message>
        <source>Done: let the job go on</source>
        <translation>Hotovo: úloha může pokračovat</translation>
    </message>
    <message>
        <source>Again</source>
        <translation>Znovu</translation>
    </message>
    <message>
        <source>It did not happen: send it again</source>
        <translation>Neproběhlo: odeslat znovu</translation>
    </message>
    <message>
        <source>Done</source>
        <translation>Hotovo</translation>
    </message>
    <message>
        <source>It happened: count it as done</source>
        <translation>Proběhlo: započítat jako hotové</translation>
    </message>
    <message>
        <source>Time left, from the dry run of the job on the machine&apos;s model</source>
        <translation>Zbývající čas podle zkušebního průchodu úlohy na modelu stroje</translation>
    </message>
    <message>
        <source>Open a job</source>
        <translation>Otevřít úlohu</translation>
    </message>
    <message>
        <source>{0}: not opened — a job is under way (abort it first)</source>
        <translation>{0}: neotevřeno — probíhá úloha (nejdřív ji přerušte)</translation>
    </message>
    <message>
        <source>{0}: not opened — still reading {1}</source>
        <translation>{0}: neotevřeno — ještě se načítá {1}</translation>
    </message>
    <message>
        <source>reading {0}…</source>
        <translation>načítám {0}…</translation>
    </message>
    <message>
        <source>{0}: not loaded — {1}</source>
        <translation>{0}: nenačteno — {1}</translation>
    </message>
    <message>
        <source>{0} — not loaded</source>
        <translation>{0} — nenačteno</translation>
    </message>
    <message numerus="yes">
        <source>… and %n more line(s) refused</source>
        <translation>
            <numerusform>… a odmítnut ještě %n další řádek</numerusform>
            <numerusform>… a odmítnuty ještě %n další řádky</numerusform>
            <numerusform>… a odmítnuto ještě %n dalších řádků</numerusform>
        </translation>
    </message>
    <message>
        <source>{0}: the board placement was not applied: {1}</source>
        <translation>{0}: umístění desky nebylo použito: {1}</translation>
    </message>
    <message>
        <source>{0}: kept on the board as before ({1})</source>
        <translation>{0}: ponecháno na desce jako předtím ({1})</translation>
    </message>
    <message>
        <source>{0} — refused, preview only</source>
        <translation>{0} — odmítnuto, jen náhled</translation>
    </message>
    <message numerus="yes">
        <source>{0}: %n operation(s) loaded</source>
        <translation>
            <numerusform>{0}: načtena %n operace</numerusform>
            <numerusform>{0}: načteny %n operace</numerusform>
            <numerusform>{0}: načteno %n operací</numerusform>
        </translation>
    </message>
    <message>
        <source>loaded</source>
        <translation>načteno</translation>
    </message>
    <message>
        <source>SD-card files (param.txt, poradi.txt)…</source>
        <translation>Soubory pro SD kartu (param.txt, poradi.txt)…</translation>
    </message>
    <message>
        <source>G-code program…</source>
        <translation>Program v G-kódu…</translation>
    </message>
    <message>
        <source>Nothing to export for this job on this machine</source>
        <translation>U této úlohy na tomto stroji není co exportovat</translation>
    </message>
    <message>
        <source>Folder for param.txt and poradi.txt</source>
        <translation>Složka pro param.txt a poradi.txt</translation>
    </message>
    <message>
        <source>Export G-code</source>
        <translation>Exportovat G-kód</translation>
    </message>
    <message>
        <source>G-code (*.gcode)</source>
        <translation>G-kód (*.gcode)</translation>
    </message>
    <message>
        <source>Only string-art jobs have SD-card files</source>
        <translation>Soubory pro SD kartu mají jen úlohy string art</translation>
    </message>
    <message>
        <source>SD-card files not written: {0}</source>
        <translation>Soubory pro SD kartu nezapsány: {0}</translation>
    </message>
    <message>
        <source>Wrote {0} and {1}</source>
        <translation>Zapsáno {0} a {1}</translation>
    </message>
    <message>
        <source>G-code not written: {0}</source>
        <translation>G-kód nezapsán: {0}</translation>
    </message>
    <message>
        <source>Wrote {0}</source>
        <translation>Zapsáno {0}</translation>
    </message>
    <message numerus="yes">
        <source>{0} — %n operation(s)</source>
        <translation>
            <numerusform>{0} — %n operace</numerusform>
            <numerusform>{0} — %n operace</numerusform>
            <numerusform>{0} — %n operací</numerusform>
        </translation>
    </message>
    <message>
        <source>the end</source>
        <translation>konec</translation>
    </message>
    <message numerus="yes">
        <source>An interrupted run of &lt;b&gt;{0}&lt;/b&gt; completed {1} of %n operation(s). Resume from operation {2} ({3})?</source>
        <translation>
            <numerusform>Přerušený běh &lt;b&gt;{0}&lt;/b&gt; dokončil {1} z %n operace. Pokračovat od operace {2} ({3})?</numerusform>
            <numerusform>Přerušený běh &lt;b&gt;{0}&lt;/b&gt; dokončil {1} z %n operací. Pokračovat od operace {2} ({3})?</numerusform>
            <numerusform>Přerušený běh &lt;b&gt;{0}&lt;/b&gt; dokončil {1} z %n operací. Pokračovat od operace {2} ({3})?</numerusform>
        </translation>
    </message>
    <message>
        <source>Resume from op {0}</source>
        <translation>Pokračovat od op. {0}</translation>
    </message>
    <message>
        <source> — motion locked: {0}</source>
        <translation> — pohyb zablokován: {0}</translation>
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
        <translation>odesláno {0}</translation>
    </message>
    <message>
        <source>Operations the machine reported as run, of all; and how many were sent to it (a G-code machine holds sent lines in its planner before it runs them)</source>
        <translation>Operace, které stroj ohlásil jako provedené, ze všech; a kolik mu jich bylo odesláno (stroj s G-kódem drží odeslané řádky v plánovači, než je provede)</translation>
    </message>
    <message>
        <source>elapsed {0}</source>
        <translation>uplynulo {0}</translation>
    </message>
    <message>
        <source>(of which {0} waiting for you)</source>
        <translation>(z toho {0} čekání na vás)</translation>
    </message>
    <message>
        <source>left {0}</source>
        <translation>zbývá {0}</translation>
    </message>
    <message>
        <source>file: {0}</source>
        <translation>soubor: {0}</translation>
    </message>
    <message>
        <source>machine: {0} microsteps</source>
        <translation>stroj: {0} mikrokroků</translation>
    </message>
    <message>
        <source>Operator: {0}</source>
        <translation>Obsluha: {0}</translation>
    </message>
    <message>
        <source>waiting for the operator: {0}</source>
        <translation>čeká se na obsluhu: {0}</translation>
    </message>
    <message>
        <source>op {0}: {1}  {2}</source>
        <translation>op. {0}: {1}  {2}</translation>
    </message>
    <message>
        <source>Run from a line</source>
        <translation>Spustit od řádku</translation>
    </message>
    <message>
        <source>Pick the line to start from, here or by clicking its stroke in the preview. The machine goes there with the pen up, set as the file had it there (units, distance mode, feed, offsets, pen), then carries on; the lines before it count as run.</source>
        <translation>Vyberte řádek, od kterého začít, zde nebo kliknutím na jeho tah v náhledu. Stroj tam najede se zvednutým perem, nastavený tak, jak ho tam měl soubor (jednotky, režim vzdáleností, posuv, posunutí, pero), a pokračuje; řádky před ním se počítají jako provedené.</translation>
    </message>
    <message>
        <source>Run from here</source>
        <translation>Spustit odsud</translation>
    </message>
    <message>
        <source>On this machine pick the line in the list</source>
        <translation>Na tomto stroji vyberte řádek v seznamu</translation>
    </message>
    <message>
        <source>Working out the machine&apos;s state at {0}…</source>
        <translation>Zjišťuji stav stroje na {0}…</translation>
    </message>
    <message>
        <source>Run from…</source>
        <translation>Spustit od…</translation>
    </message>
    <message>
        <source>Start the job at a line you pick (list or preview) ({0})</source>
        <translation>Spustit úlohu od řádku, který vyberete (seznam nebo náhled) ({0})</translation>
    </message>
</context>
<context>
    <name>JogInput</name>
    <message>
        <source>Jog refused: {0}</source>
        <extracomment>The jog vector (one -1/0/+1 per axis) after every change. The jog the held arrow keys alone ask for (one -1/0/+1 per axis), after every change: the on-screen button for that direction shows itself pressed. Stop (Esc, a Stop button) was asked, before the session is told: a job under way must end with it, or it would set the machine going again on its own. Whether this machine jogs at all: if not, no key is a jog key. Why input is refused while disabled (said when a key or button is pressed anyway). What a tap of an arrow key moves; 0: the key jogs while held (see ``set_key_step``).</extracomment>
        <translation>Ruční posuv odmítnut: {0}</translation>
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
        <translation>Páčka {0}: 500…524 je mrtvé pásmo; po puštění se vrátí na střed</translation>
    </message>
</context>
<context>
    <name>LinkDetail</name>
    <message>
        <source>built-in emulator</source>
        <extracomment>Link details the transports give in English (protocol/ has no Qt to translate them).</extracomment>
        <translation>vestavěný emulátor</translation>
    </message>
</context>
<context>
    <name>LinkState</name>
    <message>
        <source>disconnected</source>
        <translation>odpojeno</translation>
    </message>
    <message>
        <source>connecting</source>
        <translation>připojuji</translation>
    </message>
    <message>
        <source>connected</source>
        <translation>připojeno</translation>
    </message>
    <message>
        <source>stale</source>
        <translation>bez čerstvých dat</translation>
    </message>
    <message>
        <source>lost</source>
        <translation>ztraceno</translation>
    </message>
</context>
<context>
    <name>MachineModel</name>
    <message>
        <source>not connected</source>
        <extracomment>The machine position: travel limits and every motion check use it. The work coordinate offset (GRBL&apos;s WCO: machine minus work position); 0 elsewhere. Why the operator may not jog now though the machine may move (a job under way).</extracomment>
        <translation>nepřipojeno</translation>
    </message>
    <message>
        <source>link lost</source>
        <translation>spojení ztraceno</translation>
    </message>
    <message>
        <source>sleeping — press Wake</source>
        <translation>spí — stiskněte Probudit</translation>
    </message>
</context>
<context>
    <name>MachineProfile</name>
    <message>
        <source>XY positioning stage</source>
        <extracomment>How far a reported position may stray from the path of the moves sent ([supervision] tolerance_mm): a few steps, a rounded report and a report read while the move went on. What a GRBL-compatible board executes (docs/protocols.md §4 plus the usual GRBL extras). &quot;counting&quot; (at most rx_buffer - 1 bytes unacknowledged) or &quot;ping-pong&quot; G1/G2/G3 need a feed rate set first (GRBL&apos;s error:22); False: the firmware has a default. The unit of ``G4 P``: &quot;s&quot; on GRBL (P150 is two and a half minutes), &quot;ms&quot; on firmwares that read it as Marlin does. The loader, the estimate and the emulator follow it. GRBL&apos;s ``$11`` (mm): the board joins moves at their junction speed, planning ``planner_blocks`` ahead, and the estimate plans as it does; None (firmwares without a look-ahead planner): every move starts and ends at rest. A bare ``G92`` makes the current position the origin (the CoreXY plotter&apos;s firmware); False: GRBL&apos;s, which refuses it (error:26) and needs the axes named. The board answers a line only once its motion is done (the CoreXY plotter), not once planned (GRBL): every answered line ran, and an unanswered one is at most the one under way — what a resume after a fault can take as proven. A firmware that ignores F and runs G0 as G1, stepping its lead motor at one interval that only ``M98 &lt;µs&gt;`` changes (the CoreXY plotter, FIDELITY S1-01): its power-on interval in µs. None: F sets the speed (GRBL, the winder). A GRBL board&apos;s job lines go compact (:attr:`compact_lines`); False: as written.</extracomment>
        <translation>Polohovací stůl XY</translation>
    </message>
    <message>
        <source>Three-axis USB unit</source>
        <translation>Tříosá jednotka USB</translation>
    </message>
    <message>
        <source>PCB drill/plotter</source>
        <translation>Vrtačka/plotr plošných spojů</translation>
    </message>
    <message>
        <source>String-art winder</source>
        <translation>Navíječka string-artu</translation>
    </message>
    <message>
        <source>CoreXY pen plotter</source>
        <translation>Perový plotr CoreXY</translation>
    </message>
    <message>
        <source>GRBL pen plotter</source>
        <translation>Perový plotr GRBL</translation>
    </message>
</context>
<context>
    <name>MacroEditor</name>
    <message>
        <source>Macros — {0}</source>
        <translation>Makra — {0}</translation>
    </message>
    <message>
        <source>&amp;Name</source>
        <translation>&amp;Název</translation>
    </message>
    <message>
        <source>&amp;G-code</source>
        <translation>&amp;G-kód</translation>
    </message>
    <message>
        <source>&amp;Add</source>
        <translation>&amp;Přidat</translation>
    </message>
    <message>
        <source>&amp;Delete</source>
        <translation>&amp;Smazat</translation>
    </message>
    <message>
        <source>&amp;Up</source>
        <translation>Nahor&amp;u</translation>
    </message>
    <message>
        <source>Do&amp;wn</source>
        <translation>Dol&amp;ů</translation>
    </message>
    <message>
        <source>&amp;Import…</source>
        <translation>&amp;Importovat…</translation>
    </message>
    <message>
        <source>&amp;Export…</source>
        <translation>&amp;Exportovat…</translation>
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
        <translation>Importovat makra</translation>
    </message>
    <message>
        <source>Macro files (*.toml)</source>
        <translation>Soubory maker (*.toml)</translation>
    </message>
    <message>
        <source>{0} macro(s) imported</source>
        <translation>Importováno maker: {0}</translation>
    </message>
    <message>
        <source>Export macros</source>
        <translation>Exportovat makra</translation>
    </message>
    <message>
        <source>Exported to {0}</source>
        <translation>Exportováno do {0}</translation>
    </message>
</context>
<context>
    <name>Macros</name>
    <message>
        <source>no G-code to send in the macro</source>
        <translation>makro neobsahuje žádný G-kód k odeslání</translation>
    </message>
    <message>
        <source>{0}: {1} {2:g} is outside the travel {3:g}…{4:g}</source>
        <translation>{0}: {1} {2:g} je mimo rozsah pojezdu {3:g}…{4:g}</translation>
    </message>
    <message>
        <source>a macro is under way — stop it or let it finish</source>
        <extracomment>Refusals listed in a message; more are counted.</extracomment>
        <translation>běží makro — zastavte ho, nebo ho nechte doběhnout</translation>
    </message>
    <message>
        <source>… and {0} more</source>
        <translation>… a dalších {0}</translation>
    </message>
    <message>
        <source>{0} takes no G-code macros</source>
        <extracomment>The macro run&apos;s JobState. A macro&apos;s ``M0``/``M6`` asks the operator (confirm with :meth:`confirm`). The macro running, or last run. While a macro is loaded: the runner&apos;s words about an earlier run&apos;s checkpoint (a macro always starts from its start) are not the operator&apos;s business.</extracomment>
        <translation>{0} nepřijímá makra v G-kódu</translation>
    </message>
    <message>
        <source>macro {0} is running</source>
        <translation>běží makro {0}</translation>
    </message>
    <message>
        <source>not connected</source>
        <translation>nepřipojeno</translation>
    </message>
    <message>
        <source>the machine is moving</source>
        <translation>stroj se pohybuje</translation>
    </message>
    <message>
        <source>the travel check failed</source>
        <translation>kontrola pojezdu selhala</translation>
    </message>
    <message>
        <source>it did not start</source>
        <translation>nespustilo se</translation>
    </message>
    <message>
        <source>Macro {0} refused: {1}</source>
        <translation>Makro {0} odmítnuto: {1}</translation>
    </message>
    <message>
        <source>Macro {0} ended: the machine needs you first</source>
        <translation>Makro {0} ukončeno: stroj nejprve potřebuje vás</translation>
    </message>
    <message>
        <source>a macro needs a name</source>
        <extracomment>A bar of buttons, not a program library: more than this is a job file. A snippet, not a job: a few lines a person reads before pressing its button.</extracomment>
        <translation>makro potřebuje název</translation>
    </message>
    <message>
        <source>the name starts or ends with a space</source>
        <translation>název začíná nebo končí mezerou</translation>
    </message>
    <message>
        <source>the name is longer than {0} characters</source>
        <translation>název je delší než {0} znaků</translation>
    </message>
    <message>
        <source>the name may hold printable characters only, and no quote</source>
        <translation>název smí obsahovat jen tisknutelné znaky a žádné uvozovky</translation>
    </message>
    <message>
        <source>the G-code is not text</source>
        <translation>G-kód není text</translation>
    </message>
    <message>
        <source>the G-code is longer than {0} characters</source>
        <translation>G-kód je delší než {0} znaků</translation>
    </message>
    <message>
        <source>the G-code has more than {0} lines</source>
        <translation>G-kód má více než {0} řádků</translation>
    </message>
    <message>
        <source>line {0} holds a character that is not printable text</source>
        <translation>řádek {0} obsahuje netisknutelný znak</translation>
    </message>
    <message>
        <source>more than {0} macros</source>
        <translation>více než {0} maker</translation>
    </message>
    <message>
        <source>two macros are named {0}</source>
        <translation>dvě makra se jmenují {0}</translation>
    </message>
    <message>
        <source>{0}: not TOML ({1})</source>
        <extracomment>32 macros of 8000 characters, escaped, is well under this; more is not a macro file.</extracomment>
        <translation>{0}: není TOML ({1})</translation>
    </message>
    <message>
        <source>{0}: not a StepDeck macro file (format {1})</source>
        <translation>{0}: není soubor maker StepDecku (formát {1})</translation>
    </message>
    <message>
        <source>{0}: [[macro]] must be a list of at most {1} tables</source>
        <translation>{0}: [[macro]] musí být seznam nejvýše {1} tabulek</translation>
    </message>
    <message>
        <source>{0}: macro {1} is not a table</source>
        <translation>{0}: makro {1} není tabulka</translation>
    </message>
    <message>
        <source>{0}: macro {1}: {2}</source>
        <translation>{0}: makro {1}: {2}</translation>
    </message>
    <message>
        <source>{0}: not a file</source>
        <translation>{0}: není soubor</translation>
    </message>
    <message>
        <source>{0}: too large for a macro file</source>
        <translation>{0}: na soubor maker příliš velký</translation>
    </message>
    <message>
        <source>{0}: not readable ({1})</source>
        <translation>{0}: nelze přečíst ({1})</translation>
    </message>
</context>
<context>
    <name>MacrosDock</name>
    <message>
        <source>Macros</source>
        <extracomment>The dock&apos;s object name: where the window&apos;s saved layout places it. Ctrl+1 … Ctrl+9.
----------
Buttons a row.</extracomment>
        <translation>Makra</translation>
    </message>
    <message>
        <source>No macros yet: Edit… adds one.</source>
        <translation>Zatím žádná makra: přidáte je v Upravit…</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stop</translation>
    </message>
    <message>
        <source>Stop the macro (Esc)</source>
        <translation>Zastavit makro (Esc)</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Pokračovat</translation>
    </message>
    <message>
        <source>Go on after a pause or a prompt</source>
        <translation>Pokračovat po pauze nebo výzvě</translation>
    </message>
    <message>
        <source>Edit…</source>
        <translation>Upravit…</translation>
    </message>
    <message>
        <source>Add, change, order, import and export</source>
        <translation>Přidat, změnit, seřadit, importovat a exportovat</translation>
    </message>
    <message>
        <source>No macro {0}</source>
        <translation>Makro {0} neexistuje</translation>
    </message>
    <message>
        <source>Macro {0} waits: {1} — Resume when done</source>
        <translation>Makro {0} čeká: {1} — až budete hotovi, stiskněte Pokračovat</translation>
    </message>
    <message>
        <source>Macros locked: {0}</source>
        <translation>Makra zamčena: {0}</translation>
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
        <translation>{0}: zastaveno</translation>
    </message>
</context>
<context>
    <name>MainWindow</name>
    <message>
        <source>Jog X while held</source>
        <extracomment>Keys and what they do (translated where shown: QT_TRANSLATE_NOOP only marks them).</extracomment>
        <translation>Posuv v ose X, dokud je klávesa stisknutá</translation>
    </message>
    <message>
        <source>Jog Y while held (two arrows at once = diagonal)</source>
        <translation>Posuv v ose Y, dokud je klávesa stisknutá (dvě šipky naráz = šikmo)</translation>
    </message>
    <message>
        <source>Jog Z while held, on machines with a Z axis</source>
        <translation>Posuv v ose Z, dokud je klávesa stisknutá (stroje s osou Z)</translation>
    </message>
    <message>
        <source>Shift (held)</source>
        <translation>Shift (držený)</translation>
    </message>
    <message>
        <source>Jog and move at the other speed</source>
        <translation>Posuv a pohyb druhou rychlostí</translation>
    </message>
    <message>
        <source>Stop everything, from anywhere in the window</source>
        <translation>Zastavit vše, odkudkoli v okně</translation>
    </message>
    <message>
        <source>Manual / Absolute / Relative / Dynamics / Link / Axes / G-code / Settings page</source>
        <translation>Stránka Manuální / Absolutně / Relativně / Dynamika / Spojení / Osy / G-kód / Nastavení</translation>
    </message>
    <message>
        <source>Open a job (File → Open job…)</source>
        <translation>Otevřít úlohu (Soubor → Otevřít úlohu…)</translation>
    </message>
    <message>
        <source>Run the job from a line you pick (Jobs → Run from…)</source>
        <translation>Spustit úlohu od řádku, který vyberete (Úlohy → Spustit od…)</translation>
    </message>
    <message>
        <source>Quit (stops the machine first)</source>
        <translation>Ukončit (nejprve zastaví stroj)</translation>
    </message>
    <message>
        <source>Show or hide the jobs dock</source>
        <translation>Zobrazit nebo skrýt panel úloh</translation>
    </message>
    <message>
        <source>Show or hide the telemetry plots</source>
        <translation>Zobrazit nebo skrýt grafy telemetrie</translation>
    </message>
    <message>
        <source>Show or hide the developer pane</source>
        <translation>Zobrazit nebo skrýt vývojářský panel</translation>
    </message>
    <message>
        <source>Show or hide the macros (G-code machines)</source>
        <translation>Zobrazit nebo skrýt makra (stroje na G-kód)</translation>
    </message>
    <message>
        <source>Run macro 1 … 9 (G-code machines)</source>
        <translation>Spustit makro 1 … 9 (stroje na G-kód)</translation>
    </message>
    <message>
        <source>This list</source>
        <translation>Tento přehled</translation>
    </message>
    <message>
        <source>StepDeck — {0}</source>
        <extracomment>The operator chose another machine profile; the launcher rebuilds station and window. Where a language switch compiles its translation (None: the station&apos;s cache). This machine&apos;s own settings (arrow keys, link, skipped lines), apart from others&apos;. The box listing settings the station could not use (None: there were none).</extracomment>
        <translation>StepDeck — {0}</translation>
    </message>
    <message>
        <source>&amp;Manual</source>
        <extracomment>A page with motion controls: the motion lock turns it off. Adds a page button: its title, the page, its tooltip (both made again on a language switch). Every page with motion controls, for the motion lock. GRBL&apos;s $$ or the usb3 unit&apos;s EEPROM values (:mod:`widgets.panels.stored_settings`). The Dynamics page: the panel in a scroll area that only scrolls up and down.</extracomment>
        <translation>&amp;Manuální</translation>
    </message>
    <message>
        <source>Hold-to-jog buttons, Home (Alt+M)</source>
        <translation>Tlačítka posuvu (držet), reference (Alt+M)</translation>
    </message>
    <message>
        <source>D&amp;rill</source>
        <translation>V&amp;rtačka</translation>
    </message>
    <message>
        <source>Command buttons, X/Y, terminal (Alt+R)</source>
        <translation>Tlačítka příkazů, X/Y, terminál (Alt+R)</translation>
    </message>
    <message>
        <source>A&amp;xes</source>
        <translation>Osy (&amp;X)</translation>
    </message>
    <message>
        <source>Move by mm, step size, thread (Alt+X)</source>
        <translation>Posun o mm, mikrokrok, stoupání závitu (Alt+X)</translation>
    </message>
    <message>
        <source>&amp;Absolute</source>
        <translation>&amp;Absolutně</translation>
    </message>
    <message>
        <source>Move to a target (Alt+A)</source>
        <translation>Najet na zadanou polohu (Alt+A)</translation>
    </message>
    <message>
        <source>&amp;Relative</source>
        <translation>&amp;Relativně</translation>
    </message>
    <message>
        <source>Move by an increment (Alt+R)</source>
        <translation>Posunout o přírůstek (Alt+R)</translation>
    </message>
    <message>
        <source>&amp;G-code</source>
        <translation>&amp;G-kód</translation>
    </message>
    <message>
        <source>Console, pen, hold/resume/reset (Alt+G)</source>
        <translation>Konzole, pero, pozastavení/pokračování/reset (Alt+G)</translation>
    </message>
    <message>
        <source>&amp;Dynamics</source>
        <translation>&amp;Dynamika</translation>
    </message>
    <message>
        <source>Device parameters (Alt+D)</source>
        <translation>Parametry zařízení (Alt+D)</translation>
    </message>
    <message>
        <source>Se&amp;ttings</source>
        <translation>Nas&amp;tavení</translation>
    </message>
    <message>
        <source>Stored settings: read, edit, snapshots (Alt+T)</source>
        <translation>Uložená nastavení: čtení, úpravy, zálohy (Alt+T)</translation>
    </message>
    <message>
        <source>&amp;Link</source>
        <translation>Spojení (&amp;L)</translation>
    </message>
    <message>
        <source>Connect: emulator, serial port or BLE (Alt+L)</source>
        <translation>Připojení: emulátor, sériový port nebo BLE (Alt+L)</translation>
    </message>
    <message>
        <source>&amp;Colours</source>
        <translation>&amp;Barvy</translation>
    </message>
    <message>
        <source>As the &amp;system</source>
        <translation>Podle &amp;systému</translation>
    </message>
    <message>
        <source>&amp;Light</source>
        <translation>&amp;Světlé</translation>
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
        <translation>Rámce ze zařízení, které nešlo dekódovat</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Soubor</translation>
    </message>
    <message>
        <source>&amp;Open job…</source>
        <translation>&amp;Otevřít úlohu…</translation>
    </message>
    <message>
        <source>&amp;Recent jobs</source>
        <translation>&amp;Nedávné úlohy</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Ukončit</translation>
    </message>
    <message>
        <source>&amp;Machine</source>
        <translation>S&amp;troj</translation>
    </message>
    <message>
        <source>&amp;Connect</source>
        <translation>&amp;Připojit</translation>
    </message>
    <message>
        <source>&amp;Disconnect</source>
        <translation>&amp;Odpojit</translation>
    </message>
    <message>
        <source>&amp;Stop</source>
        <translation>&amp;Zastavit</translation>
    </message>
    <message>
        <source>&amp;Drop the queue</source>
        <translation>&amp;Zahodit frontu příkazů</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Zobrazení</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Nápověda</translation>
    </message>
    <message>
        <source>&amp;Keys</source>
        <translation>&amp;Klávesy</translation>
    </message>
    <message>
        <source>&amp;About StepDeck</source>
        <translation>&amp;O programu StepDeck</translation>
    </message>
    <message>
        <source>(none yet)</source>
        <translation>(zatím žádné)</translation>
    </message>
    <message>
        <source>&amp;Clear the list</source>
        <translation>&amp;Vymazat seznam</translation>
    </message>
    <message>
        <source>{0}: not opened — the file is no longer there</source>
        <translation>{0}: neotevřeno — soubor už neexistuje</translation>
    </message>
    <message>
        <source>A control station for small stepper machines: XY stages, a PCB drill, G-code plotters, the usb3 unit and the string-art winder.</source>
        <translation>Řídicí stanice pro malé stroje s krokovými motory: XY stolky, vrtačku plošných spojů, plotry na G-kód, jednotku usb3 a navíječku pro string art.</translation>
    </message>
    <message>
        <source>Machine: {0}</source>
        <translation>Stroj: {0}</translation>
    </message>
    <message>
        <source>About StepDeck</source>
        <translation>O programu StepDeck</translation>
    </message>
    <message>
        <source>Arrows do not jog while a text or number field has focus: there they keep editing. Esc works from anywhere in the window and also closes an open menu; in a dialog (like this one) Esc closes the dialog only.</source>
        <translation>Když je aktivní textové nebo číselné pole, šipky strojem nepohybují, ale upravují text. Esc funguje odkudkoli v okně a zavře i otevřenou nabídku; v dialogu (jako je tento) Esc jen zavře dialog.</translation>
    </message>
    <message>
        <source>StepDeck — keyboard shortcuts</source>
        <translation>StepDeck — klávesové zkratky</translation>
    </message>
    <message>
        <source>Motion locked: {0}</source>
        <translation>Pohyb zablokován: {0}</translation>
    </message>
    <message>
        <source>Link {0}</source>
        <translation>Spojení: {0}</translation>
    </message>
    <message numerus="yes">
        <source>rejected frames: %n</source>
        <translation>
            <numerusform>%n odmítnutý rámec</numerusform>
            <numerusform>%n odmítnuté rámce</numerusform>
            <numerusform>%n odmítnutých rámců</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n settings could not be used; defaults are used instead</source>
        <translation>
            <numerusform>%n nastavení nešlo použít; platí výchozí hodnota</numerusform>
            <numerusform>%n nastavení nešlo použít; platí výchozí hodnoty</numerusform>
            <numerusform>%n nastavení nešlo použít; platí výchozí hodnoty</numerusform>
        </translation>
    </message>
    <message>
        <source>StepDeck — settings</source>
        <translation>StepDeck — nastavení</translation>
    </message>
    <message>
        <source>Stopping every axis before closing…</source>
        <translation>Před zavřením zastavuji všechny osy…</translation>
    </message>
    <message>
        <source>Feed override -10 % / +10 %, on GRBL machines</source>
        <translation>Korekce posuvu -10 % / +10 %, na strojích s GRBL</translation>
    </message>
    <message>
        <source>Feed override -1 % / +1 %, on GRBL machines</source>
        <translation>Korekce posuvu -1 % / +1 %, na strojích s GRBL</translation>
    </message>
    <message>
        <source>Feed override back to 100 %, on GRBL machines</source>
        <translation>Korekce posuvu zpět na 100 %, na strojích s GRBL</translation>
    </message>
    <message>
        <source>Rapid override 100 → 50 → 25 %, on GRBL machines</source>
        <translation>Korekce rychloposuvu 100 → 50 → 25 %, na strojích s GRBL</translation>
    </message>
    <message>
        <source>&amp;Overrides</source>
        <translation>&amp;Korekce</translation>
    </message>
</context>
<context>
    <name>ManualPanel</name>
    <message>
        <source>Hold to jog {0}  (keys: {1}; Shift = other speed)</source>
        <extracomment>(row, column) in the cross → (dx, dy, label, key hint); ``{0}``/``{1}`` are the profile&apos;s first two axes (X and Y on a plotter, A and X on the string-art winder). The arrow keys&apos; step was chosen (0: continuous): the window stores it.</extracomment>
        <translation>Držením posouvat {0}  (klávesy: {1}; Shift = druhá rychlost)</translation>
    </message>
    <message>
        <source>continuous (hold)</source>
        <extracomment>Why the jog buttons are off while the machine itself may move (a job under way). Buttons shown pressed for a held arrow key (never one the mouse holds). The pad and the arrow-key choice, left out on a machine that cannot jog.</extracomment>
        <translation>plynule (držet)</translation>
    </message>
    <message>
        <source>{0} {1} per tap</source>
        <translation>{0} {1} na stisk</translation>
    </message>
    <message>
        <source>What a tap of an arrow key does: jog while held, or move one step (never past the travel)</source>
        <translation>Co udělá stisk šipky: posuv po dobu držení, nebo jeden krok (nikdy za mez pojezdu)</translation>
    </message>
    <message>
        <source>Arrow keys:</source>
        <translation>Šipky:</translation>
    </message>
    <message>
        <source>Home all</source>
        <translation>Reference všech os</translation>
    </message>
    <message>
        <source>Home every axis: the machine&apos;s home command does them all</source>
        <translation>Referenční jízda všech os: příkaz stroje je najede všechny</translation>
    </message>
    <message>
        <source>Home {0}</source>
        <translation>Reference {0}</translation>
    </message>
    <message>
        <source>Seek the {0} home switch and set {0} = 0</source>
        <translation>Najet na referenční spínač osy {0} a nastavit {0} = 0</translation>
    </message>
    <message>
        <source>Hold to jog {0} up  (key: {1})</source>
        <translation>Držením posouvat {0} nahoru  (klávesa: {1})</translation>
    </message>
    <message>
        <source>Hold to jog {0} down  (key: {1})</source>
        <translation>Držením posouvat {0} dolů  (klávesa: {1})</translation>
    </message>
    <message>
        <source>Jogging locked: {0}</source>
        <translation>Ruční posuv zablokován: {0}</translation>
    </message>
</context>
<context>
    <name>MotionGate</name>
    <message>
        <source>Motion refused: {0}</source>
        <translation>Pohyb odmítnut: {0}</translation>
    </message>
    <message>
        <source>there is no axis {0}</source>
        <extracomment>Targets this close past a limit are rounding (a move to exactly the travel end).</extracomment>
        <translation>osa {0} neexistuje</translation>
    </message>
    <message>
        <source>{0} {1} is not a position</source>
        <translation>{0} {1} není poloha</translation>
    </message>
    <message>
        <source>{0} {1} {2} is outside the travel {3}…{4} {2}</source>
        <translation>{0} {1} {2} je mimo pojezd {3}…{4} {2}</translation>
    </message>
    <message>
        <source>{0} {1} is not a distance</source>
        <translation>{0} {1} není vzdálenost</translation>
    </message>
    <message>
        <source>{0} {1} from {2}: {3}</source>
        <translation>{0} {1} z {2}: {3}</translation>
    </message>
    <message>
        <source>the motors are not released: {0}</source>
        <translation>motory nejsou uvolněny: {0}</translation>
    </message>
    <message>
        <source>the work zero stays: {0}</source>
        <translation>pracovní nula zůstává: {0}</translation>
    </message>
</context>
<context>
    <name>NumberField</name>
    <message>
        <source>Allowed: {0}</source>
        <extracomment>A number being typed: optional sign, digits, one decimal point or comma, digits. The note under a page&apos;s fields that says which one is wrong. An acceptable value was committed: Enter, focus out or an Up/Down step. The field turned acceptable or not acceptable (its buttons follow this). What follows the unit, derived from the value (e.g. a current scale&apos;s amperes).</extracomment>
        <translation>Povoleno: {0}</translation>
    </message>
    <message>
        <source>Not a number</source>
        <translation>Není číslo</translation>
    </message>
    <message>
        <source>Empty: type a number</source>
        <translation>Prázdné: zadejte číslo</translation>
    </message>
    <message>
        <source>{0} is outside {1}</source>
        <translation>{0} je mimo {1}</translation>
    </message>
    <message numerus="yes">
        <source>At most %n decimal(s)</source>
        <translation>
            <numerusform>Nejvýše %n desetinné místo</numerusform>
            <numerusform>Nejvýše %n desetinná místa</numerusform>
            <numerusform>Nejvýše %n desetinných míst</numerusform>
        </translation>
    </message>
    <message>
        <source>Whole numbers only</source>
        <translation>Jen celá čísla</translation>
    </message>
    <message>
        <source>Not sent — {0}</source>
        <translation>Neodesláno — {0}</translation>
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
        <translation>vrtání</translation>
    </message>
    <message>
        <source>pen up</source>
        <translation>pero nahoru</translation>
    </message>
    <message>
        <source>pen down</source>
        <translation>pero dolů</translation>
    </message>
    <message>
        <source>wait</source>
        <translation>čekání</translation>
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
        <translation>najet na {0}</translation>
    </message>
</context>
<context>
    <name>OverrideBox</name>
    <message>
        <source>Overrides</source>
        <translation>Korekce</translation>
    </message>
    <message>
        <source>Feed override -10 %</source>
        <translation>Korekce posuvu -10 %</translation>
    </message>
    <message>
        <source>Feed override -1 %</source>
        <translation>Korekce posuvu -1 %</translation>
    </message>
    <message>
        <source>Feed override +1 %</source>
        <translation>Korekce posuvu +1 %</translation>
    </message>
    <message>
        <source>Feed override +10 %</source>
        <translation>Korekce posuvu +10 %</translation>
    </message>
    <message>
        <source>100 %</source>
        <translation>100 %</translation>
    </message>
    <message>
        <source>Feed override back to 100 %</source>
        <translation>Korekce posuvu zpět na 100 %</translation>
    </message>
    <message>
        <source>{0} %</source>
        <translation>{0} %</translation>
    </message>
    <message>
        <source>Rapid (G0) at {0} %</source>
        <translation>Rychloposuv (G0) na {0} %</translation>
    </message>
    <message>
        <source>Feed</source>
        <translation>Posuv</translation>
    </message>
    <message>
        <source>Rapid</source>
        <translation>Rychloposuv</translation>
    </message>
    <message>
        <source>Rapid override 100 → 50 → 25 %</source>
        <translation>Korekce rychloposuvu 100 → 50 → 25 %</translation>
    </message>
</context>
<context>
    <name>Overrides</name>
    <message>
        <source>Override not sent: {0}</source>
        <extracomment>Status reports after the bytes before their effect is judged (see the module). Rounds of sending what is missing before the station gives up and says so: from 10 to 200 % a step of 10 and one of 1 at a time, on a board that merged the whole first burst. The firmware has GRBL&apos;s overrides (the registry says; False until it does). The last ``Ov:`` heard; None before any (or after a reset: 100 % then).</extracomment>
        <translation>Korekce neodeslána: {0}</translation>
    </message>
    <message>
        <source>this machine&apos;s firmware has no feed or rapid override</source>
        <translation>firmware tohoto stroje nemá korekci posuvu ani rychloposuvu</translation>
    </message>
    <message>
        <source>not connected</source>
        <translation>nepřipojeno</translation>
    </message>
    <message>
        <source>a feed override of {0} % is outside {1}…{2} %</source>
        <translation>korekce posuvu {0} % je mimo {1}…{2} %</translation>
    </message>
    <message>
        <source>a rapid override of {0} % is none of 25, 50 and 100 %</source>
        <translation>korekce rychloposuvu {0} % není 25, 50 ani 100 %</translation>
    </message>
    <message>
        <source>The board did not take the override: feed {0} %, rapid {1} % asked</source>
        <translation>Deska korekci nepřijala: požadován posuv {0} %, rychloposuv {1} %</translation>
    </message>
</context>
<context>
    <name>PenWatch</name>
    <message>
        <source>up</source>
        <translation>nahoře</translation>
    </message>
    <message>
        <source>down</source>
        <translation>dole</translation>
    </message>
    <message>
        <source>the spindle (the pen servo) on, clockwise (A:S)</source>
        <translation>vřeteno (servo pera) zapnuté, ve směru hodinových ručiček (A:S)</translation>
    </message>
    <message>
        <source>the spindle (the pen servo) on, counter-clockwise (A:C)</source>
        <translation>vřeteno (servo pera) zapnuté, proti směru hodinových ručiček (A:C)</translation>
    </message>
    <message>
        <source>the spindle (the pen servo) off</source>
        <translation>vřeteno (servo pera) vypnuté</translation>
    </message>
    <message>
        <source>the board&apos;s reset</source>
        <translation>resetu desky</translation>
    </message>
    <message>
        <source>Machine stopped: the pen is {0} after {1} ran (pen {2} sent), but the board did not report the change it makes; the line it got was not the line sent</source>
        <translation>Stroj zastaven: pero je {0} po provedení {1} (odesláno: pero {2}), ale deska změnu, kterou ten řádek způsobí, nenahlásila; dostala jiný řádek, než jaký byl odeslán</translation>
    </message>
    <message>
        <source>Machine stopped: the pen is {0} after {1} ran (pen {2} sent): the board reports {3}</source>
        <translation>Stroj zastaven: pero je {0} po provedení {1} (odesláno: pero {2}): deska hlásí {3}</translation>
    </message>
    <message>
        <source>{0} counted as answered while the moves before it still ran (GRBL answers a pen line only once they are done): a line or an answer was lost, changed or repeated on the way.</source>
        <translation>{0} byl započten jako zodpovězený, zatímco pohyby před ním ještě běžely (GRBL odpovídá na řádek pera až po jejich dokončení): řádek nebo odpověď se cestou ztratily, změnily nebo zopakovaly.</translation>
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
        <translation>Zrušit</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Zavřít</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Uložit</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Otevřít</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Použít</translation>
    </message>
    <message>
        <source>Discard</source>
        <translation>Zahodit</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Obnovit</translation>
    </message>
    <message>
        <source>Help</source>
        <translation>Nápověda</translation>
    </message>
    <message>
        <source>&amp;Yes</source>
        <translation>&amp;Ano</translation>
    </message>
    <message>
        <source>&amp;No</source>
        <translation>&amp;Ne</translation>
    </message>
</context>
<context>
    <name>RegistrationBar</name>
    <message>
        <source>The bottom side of a double-sided board: the job mirrored about its own extent</source>
        <translation>Spodní strana oboustranné desky: úloha zrcadlená v rámci svého rozsahu</translation>
    </message>
    <message>
        <source>Top side</source>
        <translation>Horní strana</translation>
    </message>
    <message>
        <source>Bottom, mirrored in X</source>
        <translation>Spodní, zrcadleno v X</translation>
    </message>
    <message>
        <source>Bottom, mirrored in Y</source>
        <translation>Spodní, zrcadleno v Y</translation>
    </message>
    <message>
        <source>Holes</source>
        <extracomment>At most this many reference holes (three: least squares with a residual). The operator wants to click reference ``k`` (0-based) in the preview; -1: stop picking. The job as its file says (what registration transforms; Clear goes back to it). How the loaded job was put on the board (side, registration).</extracomment>
        <translation>Otvory</translation>
    </message>
    <message>
        <source>Register on holes: two (or three) reference holes of the job</source>
        <translation>Zaměření podle otvorů: dva (nebo tři) referenční otvory úlohy</translation>
    </message>
    <message>
        <source>A reference hole: its number in drilling order</source>
        <translation>Referenční otvor: jeho číslo v pořadí vrtání</translation>
    </message>
    <message>
        <source>Pick</source>
        <translation>Vybrat</translation>
    </message>
    <message>
        <source>Then click the hole in the preview</source>
        <translation>Potom klikněte na otvor v náhledu</translation>
    </message>
    <message>
        <source>Here</source>
        <translation>Zde</translation>
    </message>
    <message>
        <source>The tool stands over this hole on the board: take its position</source>
        <translation>Nástroj stojí nad tímto otvorem na desce: převzít jeho polohu</translation>
    </message>
    <message>
        <source>3 points</source>
        <translation>3 body</translation>
    </message>
    <message>
        <source>A third reference hole: averaged in, and how far the points disagree shown</source>
        <translation>Třetí referenční otvor: započte se do průměru a ukáže, nakolik se body rozcházejí</translation>
    </message>
    <message>
        <source>Register</source>
        <translation>Zaměřit</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Vymazat</translation>
    </message>
    <message>
        <source>cannot mirror: {0}</source>
        <translation>nelze zrcadlit: {0}</translation>
    </message>
    <message>
        <source>reference {0} is hole {1} (X{2} Y{3} in the job)</source>
        <translation>referenční bod {0} je otvor {1} (X{2} Y{3} v úloze)</translation>
    </message>
    <message>
        <source>reference {0} (hole {1}) at X{2} Y{3}</source>
        <translation>reference {0} (otvor {1}) na X{2} Y{3}</translation>
    </message>
    <message>
        <source>registration refused: {0}</source>
        <translation>zaměření odmítnuto: {0}</translation>
    </message>
    <message>
        <source>registered: {0}</source>
        <translation>zaměřeno: {0}</translation>
    </message>
    <message>
        <source>the three points agree within {0} mm</source>
        <translation>tři body se shodují do {0} mm</translation>
    </message>
    <message>
        <source>warning: {0}</source>
        <translation>upozornění: {0}</translation>
    </message>
</context>
<context>
    <name>RelativePanel</name>
    <message>
        <source>Move by</source>
        <translation>Posunout o</translation>
    </message>
    <message>
        <source>{0} increment (Esc stops)</source>
        <translation>Přírůstek {0} (Esc zastaví)</translation>
    </message>
    <message>
        <source>Move {0} back by the increment</source>
        <translation>Posunout {0} o přírůstek zpět</translation>
    </message>
    <message>
        <source>Move {0} forward by the increment</source>
        <translation>Posunout {0} o přírůstek vpřed</translation>
    </message>
    <message>
        <source>{0} increment</source>
        <translation>Přírůstek {0}</translation>
    </message>
</context>
<context>
    <name>ResumeChoicePanel</name>
    <message>
        <source>Sent, but not proven run: pick the first line the drawing does not show yet</source>
        <extracomment>The rows&apos; data role: the operation index resuming there starts with. Rows listed at most (a resume from a checkpoint offers a window of lines).</extracomment>
        <translation>Odesláno, ale provedení není prokázáno: vyberte první řádek, který na kresbě ještě není</translation>
    </message>
    <message>
        <source>Resume from the chosen line</source>
        <translation>Pokračovat od zvoleného řádku</translation>
    </message>
    <message>
        <source>The machine goes there with the pen up, then carries on</source>
        <translation>Stroj tam přejede se zvednutým perem a pak pokračuje</translation>
    </message>
    <message>
        <source>from op {0}: {1}  {2}</source>
        <translation>od op. {0}: {1}  {2}</translation>
    </message>
    <message>
        <source>none of them: the job is at its end</source>
        <translation>žádná z nich: úloha je u konce</translation>
    </message>
</context>
<context>
    <name>RotationCross</name>
    <message>
        <source>Platform rotation relative to the last Zero (counter-clockwise positive)</source>
        <extracomment>Curve colours per axis (X, Y, Z, then whatever else a profile has). The least height of the three plots together, in pixels (a 1280 x 800 window must fit). The width of the caption (title, unit and key) beside each plot, in pixels. The least height a plot&apos;s vertical range shows (in its unit: mm, mm/s, V…).</extracomment>
        <translation>Natočení plošiny vůči poslednímu vynulování (kladně proti směru hodinových ručiček)</translation>
    </message>
    <message>
        <source>rotation
not plotted</source>
        <translation>natočení
se nevykresluje</translation>
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
        <translation>Ruční posuv odmítnut: {0}</translation>
    </message>
    <message>
        <source>Motion refused: {0}</source>
        <translation>Pohyb odmítnut: {0}</translation>
    </message>
    <message>
        <source>jogging</source>
        <extracomment>A held jog with no sign for this long that the key or button is still held ends (the station&apos;s dead-man). Longer than a keyboard&apos;s auto-repeat delay (0.25 to 0.66 s), whose repeats are the sign for a key; a held button is polled for it. A held jog ended without a release (dead-man or travel end): forget what is held. Since when the device has been silent with its port open, once that was a lost link (None: it is not); and whether it has answered since. Whether a late tick&apos;s lateness is the station&apos;s own, not counted as the device&apos;s silence (set by dialects whose ticks come from a real-time timer).</extracomment>
        <translation>ruční posuv</translation>
    </message>
    <message>
        <source>stop command</source>
        <translation>příkaz zastavení</translation>
    </message>
    <message>
        <source>{0} is at the end of its travel</source>
        <translation>{0} je na konci rozsahu pojezdu</translation>
    </message>
    <message>
        <source>relative moves</source>
        <translation>relativní pohyby</translation>
    </message>
    <message>
        <source>absolute moves</source>
        <translation>absolutní pohyby</translation>
    </message>
    <message>
        <source>The device is silent ({0}){1}; asking it every {2} s</source>
        <extracomment>Seconds a device has to give its first valid reply before the operator is told. Bytes of unrecognised replies kept to tell which machine is there instead. A device silent with its port open, or not answering since the link opened, is asked its dialect&apos;s harmless question this often: the devices that speak only when asked (usb3, the drill) would otherwise never be heard again once the line works. A tick this much later than its period means the station itself was not running (a busy computer, a stalled event loop): that time is not counted as the device&apos;s silence. :meth:`AnswerWatch._recovery_verdict`&apos;s &quot;not yet&quot;. The device answers again after a silence with its port open: None when its state is intact (nothing can have been lost), else what does not match (a reset, a position).</extracomment>
        <translation>Zařízení mlčí ({0}){1}; ptám se ho každých {2} s</translation>
    </message>
    <message>
        <source>the device answers again; checking it…</source>
        <translation>zařízení opět odpovídá; kontroluji ho…</translation>
    </message>
    <message>
        <source>The device answers again ({0} s after it was given up), its state intact</source>
        <translation>Zařízení opět odpovídá ({0} s poté, co bylo vzdáno), jeho stav je neporušený</translation>
    </message>
    <message>
        <source>The device answers again ({0} s after it was given up), but {1}</source>
        <translation>Zařízení opět odpovídá ({0} s poté, co bylo vzdáno), ale {1}</translation>
    </message>
    <message>
        <source>; its replies sound like {0}</source>
        <translation>; jeho odpovědi připomínají {0}</translation>
    </message>
    <message>
        <source>no answer: is this a {0}? Check the profile, baud and port{1}</source>
        <translation>bez odpovědi: je to opravdu {0}? Zkontrolujte profil, rychlost a port{1}</translation>
    </message>
    <message>
        <source>Axis {0}: device refused a command</source>
        <extracomment>Telemetry keys and the factor from wire units to displayed units.</extracomment>
        <translation>Osa {0}: zařízení odmítlo příkaz</translation>
    </message>
    <message>
        <source>Link lost: {0}</source>
        <translation>Spojení ztraceno: {0}</translation>
    </message>
</context>
<context>
    <name>Settings</name>
    <message>
        <source>Setting {0} in {1} was {2}; it should be {3}, so the default is used</source>
        <extracomment>Baud rates a serial port can be asked for (pyserial&apos;s own bounds on Linux). The stage&apos;s command frame period, as ``--period`` and the profiles allow it. Window geometry and dock layout blobs are a few hundred bytes; more is not ours. Suffix of the copy kept of a settings file Qt could not read. What the value must be, in words for the warning (&quot;an integer within 20…1000&quot;). The stored value as a ``T``; raises :class:`BadValue` for anything else. The page shown; the window has fewer, and checks the index again against its own count. Excellon steps the jobs dock offers, in inches. The jobs dock&apos;s reading options, by option name. The drill&apos;s timing constants as the operator set them in the station (FIDELITY S2-06), by constant name; absent: the profile&apos;s. The drill&apos;s conversion constants as the teacher set them (FIDELITY S2-42), kept per machine profile (``machines/&lt;profile&gt;/drill_conversion/…``); absent: the profile&apos;s. What one tap of an arrow key moves (mm, or degrees on a rotary axis); 0: held, continuous. How many job files File → Recent jobs lists. The job files opened last, newest first (&quot;&quot; where there is none). The window&apos;s colours: as the desktop says, or always light or dark. The language: the system locale&apos;s (English where it is none of these) or a fixed one. The jobs dock&apos;s options that concern the machine: stored per profile. Every value kept per machine profile; each key here is also where a file from before kept it for every machine (read once, then moved: see ``StationSettings._migrate``). Where the per-machine values live: ``machines/&lt;profile&gt;/&lt;key&gt;``. Every key, for the tests (and for anyone wondering what the file may hold). The warnings, translated when they are taken (see StationSettings.take_warnings).</extracomment>
        <translation>Nastavení {0} v souboru {1} mělo hodnotu {2}; má být {3}, proto se použije výchozí hodnota</translation>
    </message>
    <message>
        <source>Settings file {0} is malformed: defaults are used</source>
        <translation>Soubor nastavení {0} je poškozený: použijí se výchozí hodnoty</translation>
    </message>
    <message>
        <source>Settings file {0} is malformed: defaults are used; a copy is kept as {1}</source>
        <translation>Soubor nastavení {0} je poškozený: použijí se výchozí hodnoty; jeho kopie je uložena jako {1}</translation>
    </message>
    <message>
        <source>Settings file {0} is not readable: defaults are used</source>
        <translation>Soubor nastavení {0} nelze přečíst: použijí se výchozí hodnoty</translation>
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
        <translation>deska je ve stavu {0}: nastavení počká, až bude v klidu</translation>
    </message>
    <message>
        <source>not heard from yet</source>
        <translation>zatím neozvala</translation>
    </message>
    <message>
        <source>lines sent before are still being run</source>
        <translation>dříve odeslané řádky se ještě provádějí</translation>
    </message>
    <message>
        <source>{0} was not sent</source>
        <translation>{0} nebylo odesláno</translation>
    </message>
    <message>
        <source>$$ refused: error {0}, {1}</source>
        <translation>$$ odmítnuto: chyba {0}, {1}</translation>
    </message>
    <message>
        <source>{0}: refused, error {1}, {2}</source>
        <translation>{0}: odmítnuto, chyba {1}, {2}</translation>
    </message>
    <message>
        <source>the board was reset before it answered</source>
        <translation>deska byla resetována dřív, než odpověděla</translation>
    </message>
    <message>
        <source>not connected</source>
        <extracomment>&quot;read&quot; or &quot;write&quot;. The values the device read back as written (a write), or every value read. Why a value was not written, or why the read failed (empty: all went well). :attr:`values` changed (a read, a verified write, a report nobody asked for). A read or write ended: its :class:`Outcome`. What the settings are called in the window and in snapshots (&quot;grbl&quot;, &quot;usb3-eeprom&quot;). What the device last said it holds, by key. The last read or write&apos;s outcome (None before any). A read or write under way (&quot;read&quot;/&quot;write&quot;), None when idle. What a write under way asked for. The firmware version the device said it runs (a snapshot records it), None until it says, and for a device with no way to say it (the usb3 unit&apos;s wire has none).</extracomment>
        <translation>nepřipojeno</translation>
    </message>
    <message>
        <source>a job is running</source>
        <translation>běží úloha</translation>
    </message>
    <message>
        <source>the machine is moving</source>
        <translation>stroj se pohybuje</translation>
    </message>
    <message>
        <source>{0}: no such setting</source>
        <translation>{0}: takové nastavení není</translation>
    </message>
    <message>
        <source>not sent</source>
        <translation>neodesláno</translation>
    </message>
    <message>
        <source>nothing to write</source>
        <translation>není co zapsat</translation>
    </message>
    <message>
        <source>a read is under way</source>
        <translation>probíhá čtení</translation>
    </message>
    <message>
        <source>a write is under way</source>
        <translation>probíhá zápis</translation>
    </message>
    <message>
        <source>{0}: {1} was written, the device keeps {2}</source>
        <translation>{0}: zapsáno {1}, zařízení drží {2}</translation>
    </message>
    <message>
        <source>the link went down before the device answered</source>
        <translation>spojení spadlo dřív, než zařízení odpovědělo</translation>
    </message>
</context>
<context>
    <name>StageParameter</name>
    <message>
        <source>Fast speed</source>
        <extracomment>The parameters&apos; labels as app.machines.stage.parameters names them, for lupdate.</extracomment>
        <translation>Rychlá rychlost</translation>
    </message>
    <message>
        <source>Slow speed</source>
        <translation>Pomalá rychlost</translation>
    </message>
    <message>
        <source>Acceleration</source>
        <translation>Zrychlení</translation>
    </message>
    <message>
        <source>Start speed</source>
        <translation>Rozběhová rychlost</translation>
    </message>
    <message>
        <source>Run current (IRUN)</source>
        <translation>Proud za chodu (IRUN)</translation>
    </message>
    <message>
        <source>Hold current (IHOLD)</source>
        <translation>Přídržný proud (IHOLD)</translation>
    </message>
    <message>
        <source>Microsteps per step</source>
        <translation>Mikrokroků na krok</translation>
    </message>
    <message>
        <source>Screw lead</source>
        <translation>Stoupání šroubu</translation>
    </message>
    <message>
        <source>Full steps per rev</source>
        <translation>Celých kroků na otáčku</translation>
    </message>
    <message>
        <source>Travel (soft limit)</source>
        <translation>Pojezd (softwarový limit)</translation>
    </message>
    <message>
        <source>Encoder position</source>
        <translation>Poloha enkodéru</translation>
    </message>
    <message>
        <source>{0} must be within {1}…{2} {3}</source>
        <translation>{0} musí být v rozsahu {1}…{2} {3}</translation>
    </message>
    <message>
        <source>{0} must be a power of two</source>
        <translation>{0} musí být mocnina dvou</translation>
    </message>
</context>
<context>
    <name>StageSession</name>
    <message>
        <source>Not written: {0} {1}</source>
        <extracomment>Echoes counted past a MOVE_ABS&apos;s frame before one is believed to answer a later frame. Echoes come back in order, one per valid frame, so a lost frame or echo only makes the count lag; the margin of one more covers a duplicated or stale echo. Axes whose held jog was turned into a move to the travel end (+1/-1, 0: none). Every echoed position is judged against the moves sent (stopped when off them). Frames sent and echoes received since the link opened (see _check_moves). Per axis: the last MOVE_ABS sent and the frame count it went out with, until an echo of a later frame shows whether the stage received it.</extracomment>
        <translation>Nezapsáno: {0} {1}</translation>
    </message>
    <message>
        <source>{0} jog ends before the travel&apos;s end, at {1} mm</source>
        <extracomment>What the info panel shows; each is asked for at least once a second. Until the stage&apos;s own dynamics are read: its documented defaults (docs/protocols.md §1.4). Periods between a frame leaving and its effect being seen (frame out, echo back), on top of the braking distance when a jog is turned into a stop at the travel end. A jog stopped at the travel&apos;s end stops this far inside it: the stage&apos;s end switches sit at the travel&apos;s ends, and a jog is to stop before them, not on them.</extracomment>
        <translation>Ruční posuv {0} končí před koncem pojezdu, na {1} mm</translation>
    </message>
    <message>
        <source>nothing it reports shows whether it was switched off meanwhile</source>
        <translation>z ničeho, co hlásí, nepozná, zda bylo mezitím vypnuto</translation>
    </message>
    <message>
        <source>{0} {1}: refused, the device keeps {2}</source>
        <translation>{0} {1}: odmítnuto, zařízení ponechává {2}</translation>
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
        <translation>rychlost</translation>
    </message>
    <message>
        <source>none</source>
        <extracomment>Subscriber variables in words (docs/protocols.md §1.5).</extracomment>
        <translation>žádná</translation>
    </message>
    <message>
        <source>battery voltage</source>
        <translation>napětí baterie</translation>
    </message>
    <message>
        <source>battery charge</source>
        <translation>nabití baterie</translation>
    </message>
    <message>
        <source>charging current</source>
        <translation>nabíjecí proud</translation>
    </message>
    <message>
        <source>board temperature</source>
        <translation>teplota desky</translation>
    </message>
    <message>
        <source>rotation</source>
        <translation>natočení</translation>
    </message>
    <message>
        <source>yaw rate</source>
        <translation>rychlost otáčení</translation>
    </message>
    <message>
        <source>device flags</source>
        <translation>příznaky zařízení</translation>
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
        <translation>verze firmwaru</translation>
    </message>
    <message>
        <source>rejected frames</source>
        <translation>odmítnuté rámce</translation>
    </message>
    <message>
        <source>unknown subscriber</source>
        <translation>neznámý odběratel</translation>
    </message>
    <message>
        <source>charger</source>
        <extracomment>A field as a widget or a test hands it over: text typed or chosen, or a number. The device flags&apos; bits in words.</extracomment>
        <translation>nabíječka</translation>
    </message>
    <message>
        <source>USB</source>
        <translation>USB</translation>
    </message>
    <message>
        <source>low battery</source>
        <translation>slabá baterie</translation>
    </message>
    <message>
        <source>sleeping</source>
        <translation>spí</translation>
    </message>
    <message>
        <source>data session</source>
        <translation>datová relace</translation>
    </message>
    <message>
        <source>slow</source>
        <translation>pomalu</translation>
    </message>
    <message>
        <source>fast</source>
        <translation>rychle</translation>
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
        <translation>rychlost</translation>
    </message>
</context>
<context>
    <name>StaticPanel</name>
    <message>
        <source>Fast</source>
        <translation>Rychle</translation>
    </message>
    <message>
        <source>Jog and move at the fast speed (hold Shift for slow)</source>
        <translation>Posuv a pohyb rychlou rychlostí (se Shiftem pomalu)</translation>
    </message>
    <message>
        <source>Slow</source>
        <translation>Pomalu</translation>
    </message>
    <message>
        <source>Jog and move at the slow speed (hold Shift for fast)</source>
        <translation>Posuv a pohyb pomalou rychlostí (se Shiftem rychle)</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Rychlost</translation>
    </message>
    <message>
        <source>Shift held: slow</source>
        <translation>Shift držen: pomalu</translation>
    </message>
    <message>
        <source>Shift held: fast</source>
        <translation>Shift držen: rychle</translation>
    </message>
    <message>
        <source>Wake</source>
        <translation>Probudit</translation>
    </message>
    <message>
        <source>Sleep</source>
        <translation>Uspat</translation>
    </message>
    <message>
        <source>Wake the machine: motors on, motion controls unlocked</source>
        <translation>Probudit stroj: motory zapnuty, ovládání pohybu odemčeno</translation>
    </message>
    <message>
        <source>Put the machine to sleep: motors off, motion controls locked until Wake</source>
        <translation>Uspat stroj: motory vypnuty, ovládání pohybu zamčeno až do Probudit</translation>
    </message>
</context>
<context>
    <name>Station</name>
    <message>
        <source>Stopping every axis before closing the link…</source>
        <extracomment>The longest Disconnect or closing the window waits for the device to confirm the stop: the stage brakes from its default 10 mm/s at 20 mm/s² in 0.5 s, and says so in its next echo; a G-code board&apos;s hold takes about as long. How often the wait looks at the device&apos;s reports (in real time). A link was closed on the operator&apos;s word (after the stop, when one was awaited). The drill&apos;s timing constants changed (:meth:`set_drill_timing`): estimates are stale. The drill&apos;s conversion constants changed (:meth:`set_drill_conversion`): a loaded job is read again with them. How a job&apos;s millimetres become the drill&apos;s microsteps (FIDELITY S2-42): the profile&apos;s until the teacher changes them. Station-clock time by which the device must have confirmed the stop, while waiting.</extracomment>
        <translation>Před ukončením spojení zastavuji všechny osy…</translation>
    </message>
    <message>
        <source>The link went before the stop was confirmed; closed</source>
        <translation>Spojení spadlo dřív, než bylo zastavení potvrzeno; ukončeno</translation>
    </message>
    <message>
        <source>Every axis stopped; link closed</source>
        <translation>Všechny osy stojí; spojení ukončeno</translation>
    </message>
    <message>
        <source>The device did not confirm the stop within {0} s; link closed anyway — check that the machine stands</source>
        <translation>Zařízení nepotvrdilo zastavení do {0} s; spojení přesto ukončeno — zkontrolujte, že stroj stojí</translation>
    </message>
    <message>
        <source>Conversion constants not changed: {0}</source>
        <translation>Převodní konstanty nezměněny: {0}</translation>
    </message>
    <message>
        <source>reconnecting to {0}…</source>
        <translation>znovu se připojuji k {0}…</translation>
    </message>
    <message>
        <source>{0} — retrying in {1} s</source>
        <translation>{0} — nový pokus za {1} s</translation>
    </message>
    <message>
        <source>Internal error ({0}: {1}); machine stopped</source>
        <extracomment>``stepdeck NAME …`` runs module&apos;s ``main(argv) -&gt; int`` with the rest of the command line. Qt platforms with no screen to ask on: there, a missing choice is refused, not guessed.</extracomment>
        <translation>Vnitřní chyba ({0}: {1}); stroj zastaven</translation>
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
        <translation>Okamžitě zastavit všechny osy (Esc, odkudkoli v okně)</translation>
    </message>
    <message>
        <source>DROP QUEUE
this procedure
finishes (Esc)</source>
        <translation>ZAHODIT FRONTU
tento postup
doběhne (Esc)</translation>
    </message>
    <message>
        <source>The {0} has no stop command: this button and Esc drop the commands queued after the running one; the procedure it is running finishes</source>
        <translation>{0} nemá příkaz k zastavení: toto tlačítko a Esc zahodí příkazy ve frontě za právě prováděným; probíhající postup doběhne</translation>
    </message>
    <message>
        <source>DROP QUEUE
this move
finishes (Esc)</source>
        <translation>ZAHODIT FRONTU
tento pohyb
doběhne (Esc)</translation>
    </message>
    <message>
        <source>The {0} has no stop command: this button and Esc drop the commands queued after the running one; the move it is running finishes</source>
        <translation>{0} nemá příkaz k zastavení: toto tlačítko a Esc zahodí příkazy ve frontě za právě prováděným; probíhající pohyb doběhne</translation>
    </message>
    <message>
        <source>Stop everything, from anywhere in the window</source>
        <translation>Zastavit vše, odkudkoli v okně</translation>
    </message>
    <message>
        <source>Drop the queued commands, from anywhere (no stop command: this procedure finishes)</source>
        <translation>Zahodit příkazy ve frontě, odkudkoli (bez příkazu k zastavení: tento postup doběhne)</translation>
    </message>
    <message>
        <source>Drop the queued commands, from anywhere (no stop command: this move finishes)</source>
        <translation>Zahodit příkazy ve frontě, odkudkoli (bez příkazu k zastavení: tento pohyb doběhne)</translation>
    </message>
    <message>
        <source>■ Stop</source>
        <translation>■ Zastavit</translation>
    </message>
    <message>
        <source>■ Drop
queue</source>
        <translation>■ Zahodit
frontu</translation>
    </message>
</context>
<context>
    <name>StoredSetting</name>
    <message>
        <source>{0}: {1!r} is not a number</source>
        <extracomment>A whole number. A number with at most ``decimals`` decimals. 0 (off) or 1 (on). A whole number whose bits each mean one thing (``bits`` names them, lowest first). One of ``choices`` (a number that stands for a label). How snapshots and scripts name it: ``&quot;$110&quot;``, ``&quot;X.thread&quot;``. Bit names of a MASK, lowest bit first. A CHOICE&apos;s (value, label) pairs. Why the range is narrower than the device&apos;s own (said with a refusal), or &quot;&quot;. The translation context of the label, description and ``narrowed``. The device keeps the value as a 32-bit float (GRBL): read back, it may differ in its last digits from the one written, and still be the same. The axis a per-axis row is of: its label&apos;s ``{0}``.</extracomment>
        <translation>{0}: {1!r} není číslo</translation>
    </message>
    <message>
        <source>{0}: {1} is not a number</source>
        <translation>{0}: {1} není číslo</translation>
    </message>
    <message>
        <source>{0}: must be a whole number, not {1}</source>
        <translation>{0}: musí být celé číslo, ne {1}</translation>
    </message>
    <message>
        <source>{0}: must be within {1}…{2} {3}</source>
        <translation>{0}: musí být v rozsahu {1}…{2} {3}</translation>
    </message>
    <message>
        <source>{0}: at most {1} decimals are kept, not {2}</source>
        <translation>{0}: uloží se nejvýše {1} desetinná místa, ne {2}</translation>
    </message>
    <message>
        <source>{0}: {1} is none of the choices</source>
        <translation>{0}: {1} není žádná z možností</translation>
    </message>
</context>
<context>
    <name>StoredSettingsPanel</name>
    <message>
        <source>Read</source>
        <extracomment>Keys the operator changed since the device last said what it holds. Keys the last write read back as written (their state says so until the next read). The open &quot;write these differences?&quot; question, while it is asked.</extracomment>
        <translation>Načíst</translation>
    </message>
    <message>
        <source>Read every setting from the device</source>
        <translation>Načíst ze zařízení všechna nastavení</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Použít</translation>
    </message>
    <message>
        <source>Write the edited values, then read them back from the device</source>
        <translation>Zapsat upravené hodnoty a pak je ze zařízení přečíst zpět</translation>
    </message>
    <message>
        <source>Save snapshot…</source>
        <translation>Uložit zálohu…</translation>
    </message>
    <message>
        <source>Save every setting to a TOML file</source>
        <translation>Uložit všechna nastavení do souboru TOML</translation>
    </message>
    <message>
        <source>Load snapshot…</source>
        <translation>Načíst zálohu…</translation>
    </message>
    <message>
        <source>Show what a snapshot changes, then write only that</source>
        <translation>Ukázat, co záloha změní, a zapsat jen to</translation>
    </message>
    <message>
        <source>Setting</source>
        <translation>Nastavení</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Název</translation>
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
        <translation>0 (vypnuto) nebo 1 (zapnuto)</translation>
    </message>
    <message>
        <source>Allowed: {0}</source>
        <translation>Povoleno: {0}</translation>
    </message>
    <message>
        <source>Bits: {0}</source>
        <translation>Bity: {0}</translation>
    </message>
    <message>
        <source>Not read: {0}</source>
        <translation>Nenačteno: {0}</translation>
    </message>
    <message>
        <source>Reading from the device…</source>
        <translation>Načítám ze zařízení…</translation>
    </message>
    <message>
        <source>Nothing changed</source>
        <translation>Nic se nezměnilo</translation>
    </message>
    <message>
        <source>Not written: {0}</source>
        <translation>Nezapsáno: {0}</translation>
    </message>
    <message>
        <source>Writing, then reading back…</source>
        <translation>Zapisuji a pak čtu zpět…</translation>
    </message>
    <message>
        <source>Every setting read</source>
        <translation>Všechna nastavení načtena</translation>
    </message>
    <message>
        <source>Written and read back: {0}</source>
        <translation>Zapsáno a přečteno zpět: {0}</translation>
    </message>
    <message>
        <source>✗ refused</source>
        <translation>✗ odmítnuto</translation>
    </message>
    <message>
        <source>Save settings snapshot</source>
        <translation>Uložit zálohu nastavení</translation>
    </message>
    <message>
        <source>Settings snapshots (*.toml)</source>
        <translation>Zálohy nastavení (*.toml)</translation>
    </message>
    <message>
        <source>Load settings snapshot</source>
        <translation>Načíst zálohu nastavení</translation>
    </message>
    <message>
        <source>Not saved: {0} — press Read</source>
        <translation>Neuloženo: {0} — stiskněte Načíst</translation>
    </message>
    <message>
        <source>Snapshot saved to {0}</source>
        <translation>Záloha uložena do {0}</translation>
    </message>
    <message>
        <source>Not loaded: {0}</source>
        <translation>Nenačteno: {0}</translation>
    </message>
    <message>
        <source>{0}: the device holds every value</source>
        <translation>{0}: zařízení už drží všechny hodnoty</translation>
    </message>
    <message>
        <source>Values of {0} that differ from the device:</source>
        <translation>Hodnoty z {0}, které se liší od zařízení:</translation>
    </message>
    <message>
        <source>This snapshot was saved on firmware {0}; the device runs {1}. A setting may mean something else there: check each value before writing.</source>
        <translation>Tato záloha byla uložena s firmwarem {0}; zařízení má {1}. Nastavení tam může znamenat něco jiného: před zápisem zkontrolujte každou hodnotu.</translation>
    </message>
    <message>
        <source>This snapshot is of another machine ({0}), not {1}.</source>
        <translation>Tato záloha je z jiného stroje ({0}), ne z {1}.</translation>
    </message>
    <message>
        <source>Write anyway</source>
        <translation>Přesto zapsat</translation>
    </message>
    <message>
        <source>Write</source>
        <translation>Zapsat</translation>
    </message>
    <message>
        <source>Writing the snapshot&apos;s values, then reading back…</source>
        <translation>Zapisuji hodnoty zálohy a pak čtu zpět…</translation>
    </message>
    <message>
        <source>Snapshot not loaded</source>
        <translation>Záloha nenačtena</translation>
    </message>
    <message>
        <source>• edited</source>
        <translation>• upraveno</translation>
    </message>
    <message>
        <source>✗ not allowed</source>
        <translation>✗ nepovoleno</translation>
    </message>
    <message>
        <source>✓ read back</source>
        <translation>✓ přečteno zpět</translation>
    </message>
</context>
<context>
    <name>StringArtGeneratorDialog</name>
    <message>
        <source>Photo for string art</source>
        <extracomment>Asks for a photo to open / a folder to export into; None when the operator cancels.</extracomment>
        <translation>Fotografie pro string art</translation>
    </message>
    <message>
        <source>Folder for param.txt and poradi.txt</source>
        <translation>Složka pro param.txt a poradi.txt</translation>
    </message>
    <message>
        <source>String art from a photo</source>
        <extracomment>The thread picture was redrawn with this many threads (while generating).</extracomment>
        <translation>String art z fotografie</translation>
    </message>
    <message>
        <source>Photo…</source>
        <extracomment>How far from the centre the winder&apos;s needle goes (its X travel), if known.</extracomment>
        <translation>Fotografie…</translation>
    </message>
    <message>
        <source>Choose a PNG or JPEG photo</source>
        <translation>Vyberte fotografii PNG nebo JPEG</translation>
    </message>
    <message>
        <source>no photo chosen</source>
        <translation>žádná fotografie nevybrána</translation>
    </message>
    <message>
        <source>The photo cropped to the board</source>
        <translation>Fotografie oříznutá na desku</translation>
    </message>
    <message>
        <source>The thread, as wound at the real width</source>
        <translation>Nit, jak bude navinuta ve skutečné šířce</translation>
    </message>
    <message>
        <source>Photo on the board</source>
        <translation>Fotografie na desce</translation>
    </message>
    <message>
        <source>Thread</source>
        <translation>Nit</translation>
    </message>
    <message>
        <source>Choose a photo</source>
        <translation>Vyberte fotografii</translation>
    </message>
    <message>
        <source>Generate</source>
        <translation>Vytvořit</translation>
    </message>
    <message>
        <source>Make the nail sequence</source>
        <translation>Vytvořit pořadí hřebíků</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Zrušit</translation>
    </message>
    <message>
        <source>Stop; nothing is kept</source>
        <translation>Zastavit; nic se neuchová</translation>
    </message>
    <message>
        <source>Export…</source>
        <translation>Exportovat…</translation>
    </message>
    <message>
        <source>Write param.txt, poradi.txt and a PNG into a folder</source>
        <translation>Zapsat param.txt, poradi.txt a PNG do složky</translation>
    </message>
    <message>
        <source>Load as job</source>
        <translation>Načíst jako úlohu</translation>
    </message>
    <message>
        <source>Open the sequence in the jobs dock to drill and wind it</source>
        <translation>Otevřít pořadí v panelu úloh k vrtání a navíjení</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Zavřít</translation>
    </message>
    <message>
        <source>Close (a generation is cancelled)</source>
        <translation>Zavřít (probíhající výpočet se zruší)</translation>
    </message>
    <message>
        <source>circle</source>
        <translation>kruh</translation>
    </message>
    <message>
        <source>{0}-gon</source>
        <translation>{0}úhelník</translation>
    </message>
    <message>
        <source>Board radius (polomer_matrice); the nails sit 1.5 cm inside</source>
        <translation>Poloměr desky (polomer_matrice); hřebíky jsou 1,5 cm od okraje</translation>
    </message>
    <message>
        <source>The line budget</source>
        <translation>Počet čar k dispozici</translation>
    </message>
    <message>
        <source>The real thread&apos;s width: it sets how dark each thread looks</source>
        <translation>Skutečná šířka niti: určuje, jak tmavě každá nit vypadá</translation>
    </message>
    <message>
        <source>Least nails between a thread&apos;s two ends (never to a neighbouring nail)</source>
        <translation>Nejmenší počet hřebíků mezi konci niti (nikdy na sousední hřebík)</translation>
    </message>
    <message>
        <source>Pixels across the nail circle</source>
        <translation>Pixelů přes kružnici hřebíků</translation>
    </message>
    <message>
        <source>Shape</source>
        <translation>Tvar</translation>
    </message>
    <message>
        <source>Nails</source>
        <translation>Hřebíky</translation>
    </message>
    <message>
        <source>Board radius</source>
        <translation>Poloměr desky</translation>
    </message>
    <message>
        <source>Line budget</source>
        <translation>Počet čar</translation>
    </message>
    <message>
        <source>Thread width</source>
        <translation>Šířka niti</translation>
    </message>
    <message>
        <source>Minimum skip</source>
        <translation>Nejmenší přeskok</translation>
    </message>
    <message>
        <source>Raster</source>
        <translation>Rastr</translation>
    </message>
    <message>
        <source>Crop: 1 fits the photo&apos;s shorter side to the board</source>
        <translation>Ořez: 1 přizpůsobí kratší stranu fotografie desce</translation>
    </message>
    <message>
        <source>Invert (light thread, dark board)</source>
        <translation>Invertovat (světlá nit, tmavá deska)</translation>
    </message>
    <message>
        <source>Zoom</source>
        <translation>Zvětšení</translation>
    </message>
    <message>
        <source>Centre across</source>
        <translation>Střed vodorovně</translation>
    </message>
    <message>
        <source>Centre down</source>
        <translation>Střed svisle</translation>
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
        <translation>načítám &lt;b&gt;{0}&lt;/b&gt;…</translation>
    </message>
    <message>
        <source>Set the board and the crop, then Generate</source>
        <translation>Nastavte desku a ořez, pak Vytvořit</translation>
    </message>
    <message>
        <source>Not opened: {0}</source>
        <translation>Neotevřeno: {0}</translation>
    </message>
    <message>
        <source>Both pictures: the nail circle, {0} cm across, drawn {1} px wide (1 px = {2} mm).
Thread {3} mm = 1/{4} of it; chosen on a raster of {5} mm pixels.</source>
        <translation>Oba obrázky: kružnice hřebíků o průměru {0} cm vykreslená na šířku {1} px (1 px = {2} mm).
Nit {3} mm = 1/{4} průměru; voleno na rastru s pixely {5} mm.</translation>
    </message>
    <message>
        <source>Cannot generate: {0}</source>
        <translation>Nelze vytvořit: {0}</translation>
    </message>
    <message>
        <source>This winder&apos;s needle reaches {0} mm from the centre: boards up to {1} cm radius fit it (export the files for a larger one).</source>
        <translation>Jehla této navíječky dosáhne {0} mm od středu: vejdou se desky do poloměru {1} cm (pro větší soubory exportujte).</translation>
    </message>
    <message>
        <source>Preparing the lines between the nails…</source>
        <translation>Připravuji čáry mezi hřebíky…</translation>
    </message>
    <message>
        <source>Cancelling…</source>
        <translation>Ruším…</translation>
    </message>
    <message>
        <source>Preparing the lines between the nails: {0} of {1}</source>
        <translation>Připravuji čáry mezi hřebíky: {0} z {1}</translation>
    </message>
    <message>
        <source>Winding: {0} threads of at most {1}</source>
        <translation>Navíjení: {0} nití z nejvýše {1}</translation>
    </message>
    <message>
        <source>stopped before the budget: no further thread brings it closer</source>
        <translation>zastaveno před vyčerpáním: žádná další nit obraz nezlepší</translation>
    </message>
    <message>
        <source>the whole budget</source>
        <translation>celý počet</translation>
    </message>
    <message numerus="yes">
        <source>%n thread(s) ({0}), {1} m of thread; {2}; {3} s</source>
        <translation>
            <numerusform>%n nit ({0}), {1} m niti; {2}; {3} s</numerusform>
            <numerusform>%n nitě ({0}), {1} m niti; {2}; {3} s</numerusform>
            <numerusform>%n nití ({0}), {1} m niti; {2}; {3} s</numerusform>
        </translation>
    </message>
    <message>
        <source>Cancelled: nothing kept</source>
        <translation>Zrušeno: nic neuchováno</translation>
    </message>
    <message>
        <source>Generation failed: {0}</source>
        <translation>Výpočet selhal: {0}</translation>
    </message>
    <message>
        <source>Nothing written to {0}: {1}</source>
        <translation>Do {0} nic nezapsáno: {1}</translation>
    </message>
    <message>
        <source>Wrote {0} in {1}</source>
        <translation>Zapsáno {0} do {1}</translation>
    </message>
    <message>
        <source>Not loaded: nothing written to {0}: {1}</source>
        <translation>Nenačteno: do {0} nic nezapsáno: {1}</translation>
    </message>
    <message>
        <source>Not loaded: see the jobs dock&apos;s messages</source>
        <translation>Nenačteno: viz zprávy v panelu úloh</translation>
    </message>
</context>
<context>
    <name>Supervision</name>
    <message>
        <source>outside the travel</source>
        <translation>mimo pojezd</translation>
    </message>
    <message>
        <source>past the target</source>
        <translation>za cílem</translation>
    </message>
    <message>
        <source>moved while nothing was sent</source>
        <translation>pohnul se, ačkoli nic nebylo odesláno</translation>
    </message>
    <message>
        <source>off the path of the moves sent</source>
        <translation>mimo dráhu odeslaných pohybů</translation>
    </message>
    <message>
        <source>no move</source>
        <translation>žádný pohyb</translation>
    </message>
    <message>
        <source>Machine stopped: it reported {0}, {1} ({2}); expected {3}, {4} mm away</source>
        <translation>Stroj zastaven: hlásil {0}, {1} ({2}); očekáváno {3}, vzdálenost {4} mm</translation>
    </message>
</context>
<context>
    <name>TelemetryDock</name>
    <message>
        <source>Telemetry</source>
        <translation>Telemetrie</translation>
    </message>
    <message>
        <source>Variable</source>
        <translation>Proměnná</translation>
    </message>
    <message>
        <source>Subscriber variable to plot; the station asks for it in every frame the info panel does not need</source>
        <translation>Proměnná odběratele k vykreslení; stanice si ji vyžádá v každém rámci, který nepotřebuje informační panel</translation>
    </message>
    <message>
        <source>none</source>
        <translation>žádná</translation>
    </message>
    <message>
        <source>Window</source>
        <translation>Okno</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pozastavit</translation>
    </message>
    <message>
        <source>Freeze the plots; recording goes on</source>
        <translation>Zmrazit grafy; záznam pokračuje</translation>
    </message>
    <message>
        <source>Autoscale</source>
        <translation>Automatické měřítko</translation>
    </message>
    <message>
        <source>Fit each plot&apos;s vertical range to what is shown (dragging a plot turns it off)</source>
        <translation>Přizpůsobit svislý rozsah každého grafu zobrazeným datům (tažení grafu to vypne)</translation>
    </message>
    <message>
        <source>Export CSV…</source>
        <translation>Exportovat CSV…</translation>
    </message>
    <message>
        <source>Save the samples shown, with units, as CSV</source>
        <translation>Uložit zobrazené vzorky s jednotkami jako CSV</translation>
    </message>
    <message>
        <source>Export PNG…</source>
        <translation>Exportovat PNG…</translation>
    </message>
    <message>
        <source>Save the plots as an image</source>
        <translation>Uložit grafy jako obrázek</translation>
    </message>
    <message>
        <source>paused — recording goes on</source>
        <translation>pozastaveno — záznam pokračuje</translation>
    </message>
    <message>
        <source>position</source>
        <translation>poloha</translation>
    </message>
    <message>
        <source>velocity</source>
        <translation>rychlost</translation>
    </message>
    <message>
        <source>time before the pause</source>
        <translation>čas před pozastavením</translation>
    </message>
    <message>
        <source>time before now</source>
        <translation>čas před okamžikem</translation>
    </message>
    <message>
        <source>Rotation</source>
        <translation>Natočení</translation>
    </message>
    <message>
        <source>Zero</source>
        <translation>Vynulovat</translation>
    </message>
    <message>
        <source>Make the present angle read 0°</source>
        <translation>Nastavit současný úhel na 0°</translation>
    </message>
    <message>
        <source>Paused</source>
        <translation>Pozastaveno</translation>
    </message>
    <message>
        <source>Export telemetry as CSV</source>
        <translation>Exportovat telemetrii jako CSV</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>Soubory CSV (*.csv)</translation>
    </message>
    <message>
        <source>Export telemetry plots as PNG</source>
        <translation>Exportovat grafy telemetrie jako PNG</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>Obrázky PNG (*.png)</translation>
    </message>
    <message>
        <source>variable (none)</source>
        <translation>proměnná (žádná)</translation>
    </message>
    <message>
        <source>This machine reports no subscriber variables</source>
        <translation>Tento stroj nehlásí žádné proměnné odběratele</translation>
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
        <translation>kroků</translation>
    </message>
    <message>
        <source>µsteps</source>
        <translation>µkroků</translation>
    </message>
    <message>
        <source>mm/rev</source>
        <translation>mm/ot</translation>
    </message>
    <message>
        <source>frames</source>
        <translation>rámců</translation>
    </message>
    <message>
        <source>step/mm</source>
        <extracomment>The unit words of the stored settings, for lupdate (symbols like mm pass unchanged; the window&apos;s :mod:`widgets.units` says the others in the same context).</extracomment>
        <translation>kroků/mm</translation>
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
        <translation>Posunout o</translation>
    </message>
    <message>
        <source>Will move</source>
        <translation>Skutečně ujede</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Krok</translation>
    </message>
    <message>
        <source>Thread</source>
        <translation>Nit</translation>
    </message>
    <message>
        <source>Signed distance to move {0} (fractions allowed)</source>
        <translation>Vzdálenost se znaménkem pro posun {0} (i desetinná)</translation>
    </message>
    <message>
        <source>The unit moves in whole steps: this is what it will really move</source>
        <translation>Jednotka se pohybuje po celých krocích: tolik skutečně ujede</translation>
    </message>
    <message>
        <source>full</source>
        <comment>full step</comment>
        <translation>celý</translation>
    </message>
    <message>
        <source>Send {0}</source>
        <translation>Odeslat {0}</translation>
    </message>
    <message>
        <source>{0} distance</source>
        <translation>Vzdálenost {0}</translation>
    </message>
    <message>
        <source>Zero all</source>
        <translation>Vynulovat vše</translation>
    </message>
    <message>
        <source>Set every axis&apos; position to 0 where it stands (C;)</source>
        <translation>Nastavit polohu všech os tam, kde stojí, na 0 (C;)</translation>
    </message>
    <message>
        <source>Send all</source>
        <translation>Odeslat vše</translation>
    </message>
    <message>
        <source>Move every axis by its distance, all starting together</source>
        <translation>Posune každou osu o její vzdálenost, všechny se rozjedou zároveň</translation>
    </message>
    <message>
        <source>The unit moves in whole steps; top speed at this step size {0} mm/s</source>
        <translation>Jednotka se pohybuje po celých krocích; nejvyšší rychlost při tomto kroku {0} mm/s</translation>
    </message>
</context>
<context>
    <name>Usb3Session</name>
    <message>
        <source>{0}: {1} mm is less than one step</source>
        <extracomment>How far ahead of the key a jog keeps the axis, in seconds of travel at top rate. Seconds without any reply before the unit is asked ``G;``, then late (amber), then lost. ``C;`` was sent and the axis has not reported since: its next report is a new zero. Asked where it stands (a move of nothing) and not answered yet: its next report is where it stands, not a motion. Axes asked where they stand at rest, which must stand (a question run as a move). Where the jog leads sent so far take each axis (None: from its position). Per axis: the count the moves sent are heading for, their direction and when the last was sent (None: no move of the station&apos;s under way). Per axis: the count it stood at when a move was sent to it at rest (None: none). Station-clock time of the unit&apos;s last ``?;`` (None: none on this link). The direction register as the station last set it (``D``). Station-clock time of each axis&apos;s last position report. Per axis, the path (in counts) of the moves sent that the reports must follow. After a silence: per axis, the counts the unit may stand at (from where it was to where the moves sent take it), and whether it has been asked where it stands. Each axis&apos;s count when the silence began (what it answers if nothing sent meanwhile ran). Which settings reports came since the link opened (the first always counts).</extracomment>
        <translation>{0}: {1} mm je méně než jeden krok</translation>
    </message>
    <message>
        <source>Nothing to move: every distance is less than one step</source>
        <translation>Není čím pohnout: každá vzdálenost je menší než jeden krok</translation>
    </message>
    <message>
        <source>This unit has no stop command: it finishes its move</source>
        <translation>Tato jednotka nemá příkaz zastavení: dokončí svůj pohyb</translation>
    </message>
    <message>
        <source>{0} {1} mm, {2} counts</source>
        <extracomment>An axis that has not reported for this long after a report has stopped. An axis stopped at an end switch: axis index, &quot;low&quot; or &quot;high&quot;, position in mm. The unit answered ``?;`` and an axis never left where its move began: the move was the command it could not read. Axis index, position in mm.</extracomment>
        <translation>{0} {1} mm, {2} dílků</translation>
    </message>
    <message>
        <source>{0} asked where it stands, a move of nothing</source>
        <translation>{0}: dotaz, kde stojí (pohyb o nic)</translation>
    </message>
    <message>
        <source>{0} stopped at its high end switch at {1} mm, {2} mm short of its target</source>
        <translation>{0} se zastavila na horním koncovém spínači na {1} mm, {2} mm před cílem</translation>
    </message>
    <message>
        <source>{0} stopped at its low end switch at {1} mm, {2} mm short of its target</source>
        <translation>{0} se zastavila na dolním koncovém spínači na {1} mm, {2} mm před cílem</translation>
    </message>
    <message>
        <source>The unit could not read the move of {0} (it answered ?;) and did not move it: {0} stands at {1} mm</source>
        <translation>Jednotka nepřečetla pohyb {0} (odpověděla ?;) a nepohnula jí: {0} stojí na {1} mm</translation>
    </message>
    <message>
        <source>Garbage from the unit dropped: {0}</source>
        <translation>Nesmyslná data od jednotky zahozena: {0}</translation>
    </message>
    <message>
        <source>The unit did not understand a command (?;)</source>
        <translation>Jednotka nerozuměla příkazu (?;)</translation>
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
        <translation>{0} velikost kroku</translation>
    </message>
    <message>
        <source>The driver&apos;s microstep: finer steps move more smoothly and more slowly (the pulse rate stays the same).</source>
        <translation>Mikrokrok budiče: jemnější kroky jedou plynuleji a pomaleji (četnost pulzů zůstává stejná).</translation>
    </message>
    <message>
        <source>{0} thread</source>
        <translation>{0} závit</translation>
    </message>
    <message>
        <source>The axis&apos;s lead screw: how far one turn moves it. It decides how the unit&apos;s counts become millimetres.</source>
        <translation>Pohybový šroub osy: jak daleko ji posune jedna otáčka. Určuje, jak se počty jednotky převádějí na milimetry.</translation>
    </message>
</context>
<context>
    <name>WorkZero</name>
    <message>
        <source>no axis to zero</source>
        <extracomment>GRBL 1.1&apos;s work coordinate systems (``N_COORDINATE_SYSTEM``). The firmware has GRBL&apos;s work systems (the registry says; False until it does). The system in use as far as known (None before the board&apos;s first reset or $G). Each system&apos;s stored offset, as the board&apos;s last ``$#`` listed it.</extracomment>
        <translation>žádná osa k vynulování</translation>
    </message>
    <message>
        <source>{0} is none of G54…G59</source>
        <translation>{0} není žádný z G54…G59</translation>
    </message>
    <message>
        <source>not sent: the board has not reported its work offset yet</source>
        <translation>neodesláno: deska ještě nenahlásila svůj pracovní posun</translation>
    </message>
    <message>
        <source>this machine&apos;s firmware has no work coordinate systems</source>
        <translation>firmware tohoto stroje nemá pracovní souřadné systémy</translation>
    </message>
    <message>
        <source>Work zero: {0}</source>
        <translation>Pracovní nula: {0}</translation>
    </message>
</context>
<context>
    <name>WorkZeroBox</name>
    <message>
        <source>Work zero</source>
        <translation>Pracovní nula</translation>
    </message>
    <message>
        <source>The coordinate system in use and its offset from the machine zero</source>
        <translation>Používaný souřadný systém a jeho posun od nuly stroje</translation>
    </message>
    <message>
        <source>Zero {0}</source>
        <translation>Nula {0}</translation>
    </message>
    <message>
        <source>Here is {0} 0 in the system in use (G10 L20 P0 {0}0); nothing moves</source>
        <translation>Zde je {0} 0 v používaném systému (G10 L20 P0 {0}0); nic se nepohne</translation>
    </message>
    <message>
        <source>Zero all</source>
        <translation>Vynulovat vše</translation>
    </message>
    <message>
        <source>Here is the work zero of every axis (G10 L20 P0); nothing moves</source>
        <translation>Zde je pracovní nula všech os (G10 L20 P0); nic se nepohne</translation>
    </message>
    <message>
        <source>Go to work zero</source>
        <translation>Na pracovní nulu</translation>
    </message>
    <message>
        <source>Lift the pen, then travel to the work zero (G90 G0)</source>
        <translation>Zvednout pero a přejet na pracovní nulu (G90 G0)</translation>
    </message>
    <message>
        <source>Read</source>
        <translation>Načíst</translation>
    </message>
    <message>
        <source>Ask the board for its systems ($G, $#)</source>
        <translation>Zeptat se desky na její systémy ($G, $#)</translation>
    </message>
    <message>
        <source>Work in {0} from now on (its own zero); nothing moves</source>
        <translation>Od teď pracovat v {0} (jeho vlastní nula); nic se nepohne</translation>
    </message>
    <message>
        <source>In use</source>
        <translation>Používá se</translation>
    </message>
</context>
</TS>

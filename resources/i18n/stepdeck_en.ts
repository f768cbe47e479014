<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en">
<context>
    <name>BoardDialog</name>
    <message numerus="yes">
        <source>&lt;b&gt;{0}&lt;/b&gt; lists %n nail visit(s) without a param.txt. Which board is it for?</source>
        <translation>
            <numerusform>&lt;b&gt;{0}&lt;/b&gt; lists %n nail visit without a param.txt. Which board is it for?</numerusform>
            <numerusform>&lt;b&gt;{0}&lt;/b&gt; lists %n nail visits without a param.txt. Which board is it for?</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>ConnectionPanel</name>
    <message numerus="yes">
        <source>%n found</source>
        <translation>
            <numerusform>%n found</numerusform>
            <numerusform>%n found</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>DynamicsPanel</name>
    <message numerus="yes">
        <source>%n value(s) written</source>
        <translation>
            <numerusform>%n value written</numerusform>
            <numerusform>%n values written</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) of {0} differ from the device:</source>
        <translation>
            <numerusform>%n value of {0} differs from the device:</numerusform>
            <numerusform>%n values of {0} differ from the device:</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Write %n</source>
        <translation>
            <numerusform>Write %n</numerusform>
            <numerusform>Write %n</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) written from the snapshot; the device confirms each</source>
        <translation>
            <numerusform>%n value written from the snapshot; the device confirms it</numerusform>
            <numerusform>%n values written from the snapshot; the device confirms each</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) written back</source>
        <translation>
            <numerusform>%n value written back</numerusform>
            <numerusform>%n values written back</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>FrameLogView</name>
    <message numerus="yes">
        <source>… %n entries not shown: the log keeps the last {0}</source>
        <translation>
            <numerusform>… %n entry not shown: the log keeps the last {0}</numerusform>
            <numerusform>… %n entries not shown: the log keeps the last {0}</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n entries</source>
        <translation>
            <numerusform>%n entry</numerusform>
            <numerusform>%n entries</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source> — paused, %n new not shown</source>
        <translation>
            <numerusform> — paused, %n new not shown</numerusform>
            <numerusform> — paused, %n new not shown</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Saved %n entries to {0}</source>
        <translation>
            <numerusform>Saved %n entry to {0}</numerusform>
            <numerusform>Saved %n entries to {0}</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>GcodePanel</name>
    <message numerus="yes">
        <source>! soft reset: %n unanswered line(s) dropped</source>
        <translation>
            <numerusform>! soft reset: %n unanswered line dropped</numerusform>
            <numerusform>! soft reset: %n unanswered lines dropped</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>JobsDock</name>
    <message numerus="yes">
        <source>… and %n more line(s) refused</source>
        <translation>
            <numerusform>… and %n more line refused</numerusform>
            <numerusform>… and %n more lines refused</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>{0}: %n operation(s) loaded</source>
        <translation>
            <numerusform>{0}: %n operation loaded</numerusform>
            <numerusform>{0}: %n operations loaded</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>{0} — %n operation(s)</source>
        <translation>
            <numerusform>{0} — %n operation</numerusform>
            <numerusform>{0} — %n operations</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>An interrupted run of &lt;b&gt;{0}&lt;/b&gt; completed {1} of %n operation(s). Resume from operation {2} ({3})?</source>
        <translation>
            <numerusform>An interrupted run of &lt;b&gt;{0}&lt;/b&gt; completed {1} of %n operation. Resume from operation {2} ({3})?</numerusform>
            <numerusform>An interrupted run of &lt;b&gt;{0}&lt;/b&gt; completed {1} of %n operations. Resume from operation {2} ({3})?</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>{0} / %n ops</source>
        <extracomment>The file ``_source_lines`` came from and the program they were read for. The board the operator gave for a bare nail list (kept while the file is re-read). The job type the operator chose for an ambiguous file (kept while it is re-read). An option changed while a file was being read: read it again when that ends. The source lines the loading thread read with the program (None: read them here).</extracomment>
        <translation>
            <numerusform>{0} / %n op</numerusform>
            <numerusform>{0} / %n ops</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>MainWindow</name>
    <message numerus="yes">
        <source>rejected frames: %n</source>
        <translation>
            <numerusform>rejected frames: %n</numerusform>
            <numerusform>rejected frames: %n</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n settings could not be used; defaults are used instead</source>
        <translation>
            <numerusform>%n setting could not be used; the default is used instead</numerusform>
            <numerusform>%n settings could not be used; defaults are used instead</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>NumberField</name>
    <message numerus="yes">
        <source>At most %n decimal(s)</source>
        <translation>
            <numerusform>At most %n decimal</numerusform>
            <numerusform>At most %n decimals</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>StringArtGeneratorDialog</name>
    <message numerus="yes">
        <source>%n thread(s) ({0}), {1} m of thread; {2}; {3} s</source>
        <translation>
            <numerusform>%n thread ({0}), {1} m of thread; {2}; {3} s</numerusform>
            <numerusform>%n threads ({0}), {1} m of thread; {2}; {3} s</numerusform>
        </translation>
    </message>
</context>
</TS>

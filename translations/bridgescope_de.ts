<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>AtomicFile</name>
    <message>
        <source>cannot create a temporary file in %1: %2</source>
        <translation>kann in %1 keine temporäre Datei anlegen: %2</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>kann %1 nicht schreiben: %2</translation>
    </message>
    <message>
        <source>cannot keep the previous file as %1: %2</source>
        <translation>kann die vorige Datei nicht als %1 behalten: %2</translation>
    </message>
    <message>
        <source>cannot keep the previous file as %1</source>
        <translation>kann die vorige Datei nicht als %1 behalten</translation>
    </message>
    <message>
        <source>cannot replace %1: %2</source>
        <translation>kann %1 nicht ersetzen: %2</translation>
    </message>
    <message>
        <source>a FIFO (named pipe)</source>
        <translation>ein FIFO (eine benannte Pipe)</translation>
    </message>
    <message>
        <source>a character device</source>
        <translation>ein zeichenorientiertes Gerät</translation>
    </message>
    <message>
        <source>a block device</source>
        <translation>ein blockorientiertes Gerät</translation>
    </message>
    <message>
        <source>a directory</source>
        <translation>ein Ordner</translation>
    </message>
    <message>
        <source>a socket</source>
        <translation>ein Socket</translation>
    </message>
    <message>
        <source>a symbolic link that leads nowhere (a loop)</source>
        <translation>ein symbolischer Link, der nirgends hinführt (eine Schleife)</translation>
    </message>
    <message>
        <source>not a regular file</source>
        <translation>keine reguläre Datei</translation>
    </message>
    <message>
        <source>cannot examine %1: %2</source>
        <translation>%1 kann nicht untersucht werden: %2</translation>
    </message>
    <message>
        <source>%1 is %2, not a regular file; only regular files are written over</source>
        <translation>%1 ist %2, keine reguläre Datei; überschrieben werden nur reguläre Dateien</translation>
    </message>
    <message>
        <source>%1 is read-only; make it writable or choose another name</source>
        <translation>%1 ist schreibgeschützt; machen Sie die Datei beschreibbar oder wählen Sie einen anderen Namen</translation>
    </message>
</context>
<context>
    <name>BagHeader</name>
    <message>
        <source>cannot read it</source>
        <translation>nicht lesbar</translation>
    </message>
    <message>
        <source>not a ROS 1 bag (no #ROSBAG V2.0 header)</source>
        <translation>kein ROS-1-Bag (kein Header #ROSBAG V2.0)</translation>
    </message>
    <message>
        <source>%1, not a file</source>
        <translation>%1, keine Datei</translation>
    </message>
</context>
<context>
    <name>BagReader</name>
    <message>
        <source>usage: bridgescope-bagreader BAG OUT.bsrun</source>
        <translation>Aufruf: bridgescope-bagreader BAG AUS.bsrun</translation>
    </message>
    <message>
        <source>the bag asks for more memory than a bag of stamps needs: it is damaged</source>
        <translation>das Bag verlangt mehr Speicher, als ein Bag mit Zeitstempeln braucht: es ist beschädigt</translation>
    </message>
    <message>
        <source>cannot read the bag: %1</source>
        <translation>das Bag ist nicht lesbar: %1</translation>
    </message>
</context>
<context>
    <name>BagReaderProcess</name>
    <message>
        <source>cannot read bags: the helper program bridgescope-bagreader is not installed</source>
        <translation>Bags sind nicht lesbar: das Hilfsprogramm bridgescope-bagreader ist nicht installiert</translation>
    </message>
    <message>
        <source>no temporary folder: %1</source>
        <translation>kein temporärer Ordner: %1</translation>
    </message>
    <message>
        <source>cannot start %1: %2</source>
        <translation>%1 lässt sich nicht starten: %2</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>the bag reader made no progress for %1 s; the bag may be damaged</source>
        <translation>der Bag-Leser kam %1 s lang nicht voran; das Bag ist vielleicht beschädigt</translation>
    </message>
    <message>
        <source>the bag is damaged: rosbag&apos;s library crashed reading it%1</source>
        <translation>das Bag ist beschädigt: die rosbag-Bibliothek ist beim Lesen abgestürzt%1</translation>
    </message>
    <message>
        <source>the bag reader failed (exit %1)</source>
        <translation>der Bag-Leser ist gescheitert (Status %1)</translation>
    </message>
    <message>
        <source>the bag reader&apos;s result does not read: %1</source>
        <translation>das Ergebnis des Bag-Lesers ist nicht lesbar: %1</translation>
    </message>
</context>
<context>
    <name>BridgeCommand</name>
    <message>
        <source>Broker URL; overrides the config&apos;s broker host and port.</source>
        <translation>Broker-URL; ersetzt Rechner und Port des Brokers aus der Konfiguration.</translation>
    </message>
    <message>
        <source>ROS master URI (default $ROS_MASTER_URI).</source>
        <translation>ROS-Master-URI (Vorgabe $ROS_MASTER_URI).</translation>
    </message>
    <message>
        <source>ROS node name (default mqtt_client).</source>
        <translation>ROS-Knotenname (Vorgabe mqtt_client).</translation>
    </message>
    <message>
        <source>Value for $(arg NAME) in the config; repeatable.</source>
        <translation>Wert für $(arg NAME) in der Konfiguration; mehrfach möglich.</translation>
    </message>
    <message>
        <source>Shift this bridge&apos;s clock (stamps, latencies) by MS milliseconds, as if it ran on a host whose clock is off.</source>
        <translation>Die Uhr dieser Bridge (Zeitstempel, Latenzen) um MS Millisekunden verschieben, als liefe sie auf einem Rechner mit falsch gehender Uhr.</translation>
    </message>
    <message>
        <source>Publish the type announcement with every message, exactly as mqtt_client v2.2.1 does (small messages then wait up to 40 ms for TCP&apos;s delayed ACK); by default once per type and connection.</source>
        <translation>Die Typankündigung mit jeder Nachricht veröffentlichen, genau wie mqtt_client v2.2.1 (kleine Nachrichten warten dann bis zu 40 ms auf das verzögerte ACK von TCP); Vorgabe: einmal je Typ und Verbindung.</translation>
    </message>
    <message>
        <source>mqtt_client config (ROS 1 or ROS 2 layout).</source>
        <translation>mqtt_client-Konfiguration (ROS-1- oder ROS-2-Layout).</translation>
    </message>
    <message>
        <source>Runs an mqtt_client config as a reference bridge between the ROS master and the broker, with mqtt_client&apos;s wire protocol (type announcements, injected stamps, latency topics, primitives) and the benchmarking suite&apos;s timestamp_topic_prefix stamps. Stops cleanly on Ctrl+C or SIGTERM.
Exit status: 0 stopped, 1 broker or master failed, 2 bad options or config.</source>
        <translation>Führt eine mqtt_client-Konfiguration als Referenz-Bridge zwischen ROS-Master und Broker aus, mit dem Übertragungsprotokoll von mqtt_client (Typankündigungen, eingefügte Zeitstempel, Latenz-Topics, Primitivwerte) und den timestamp_topic_prefix-Zeitstempeln der Benchmarking-Suite. Beendet sich sauber bei Strg+C oder SIGTERM.
Exit-Status: 0 beendet, 1 Broker oder Master ausgefallen, 2 falsche Optionen oder Konfiguration.</translation>
    </message>
    <message>
        <source>bridge takes one config file; see bridgescope bridge --help</source>
        <translation>bridge erwartet genau eine Konfigurationsdatei; siehe bridgescope bridge --help</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>--arg takes NAME=VALUE, not &apos;%1&apos;</source>
        <translation>--arg erwartet NAME=VALUE, nicht &apos;%1&apos;</translation>
    </message>
    <message>
        <source>bridge failed: %1</source>
        <translation>Bridge fehlgeschlagen: %1</translation>
    </message>
    <message numerus="yes">
        <source>bridging %n mapping(s); Ctrl+C stops</source>
        <translation>
            <numerusform>übertrage %n Zuordnung; Strg+C beendet</numerusform>
            <numerusform>übertrage %n Zuordnungen; Strg+C beendet</numerusform>
        </translation>
    </message>
    <message>
        <source>stopped: %1 messages to MQTT, %2 to ROS, %3 failed</source>
        <translation>beendet: %1 Nachrichten nach MQTT, %2 nach ROS, %3 fehlgeschlagen</translation>
    </message>
    <message>
        <source>Memory bound of the messages on their way, in MiB: half towards the broker (the oldest waiting are dropped beyond it), half towards ROS (roscpp&apos;s queues; a message beyond is dropped). Drops are counted and logged.</source>
        <translation>Speichergrenze der Nachrichten unterwegs, in MiB: die Hälfte zum Broker (darüber werden die ältesten wartenden verworfen), die Hälfte zu ROS (die Warteschlangen von roscpp; eine Nachricht darüber wird verworfen). Verworfene werden gezählt und protokolliert.</translation>
    </message>
    <message>
        <source>--max-queued-mib takes a number of MiB from 1 to 1048576</source>
        <translation>--max-queued-mib erwartet eine Anzahl MiB von 1 bis 1048576</translation>
    </message>
    <message>
        <source>memory bound (%1 MiB, --max-queued-mib): %2 messages to MQTT and %3 to ROS dropped so far, %4 MiB held now</source>
        <translation>Speichergrenze (%1 MiB, --max-queued-mib): bisher %2 Nachrichten zu MQTT und %3 zu ROS verworfen, jetzt %4 MiB gehalten</translation>
    </message>
    <message>
        <source>--broker-fd takes an open file descriptor above 2, not &apos;%1&apos;</source>
        <translation>--broker-fd erwartet einen offenen Dateideskriptor über 2, nicht &apos;%1&apos;</translation>
    </message>
    <message>
        <source>--broker-fd %1: %2</source>
        <translation>--broker-fd %1: %2</translation>
    </message>
    <message>
        <source>--broker-fd %1: more than %2 bytes; a broker URL is shorter</source>
        <translation>--broker-fd %1: mehr als %2 Bytes; eine Broker-URL ist kürzer</translation>
    </message>
    <message>
        <source>Read the broker URL, credentials included, from the open file descriptor FD (a pipe the starting process filled), not from the command line that every user sees.</source>
        <translation>Die Broker-URL samt Zugangsdaten aus dem offenen Dateideskriptor FD lesen (eine Pipe, die der startende Prozess gefüllt hat), nicht aus der Befehlszeile, die jeder Benutzer sieht.</translation>
    </message>
    <message>
        <source>give --broker or --broker-fd, not both</source>
        <translation>--broker oder --broker-fd angeben, nicht beides</translation>
    </message>
    <message>
        <source>--clock-offset-ms takes -%1 to %1 milliseconds (a day)</source>
        <translation>--clock-offset-ms erwartet -%1 bis %1 Millisekunden (einen Tag)</translation>
    </message>
    <message>
        <source>a bridge runs on one ROS: give --ros 1 or --ros 2</source>
        <translation>eine Bridge läuft auf einem ROS: --ros 1 oder --ros 2 angeben</translation>
    </message>
    <message>
        <source>--ros-master is for --ros 1; a ROS 2 bridge takes --ros-domain</source>
        <translation>--ros-master gilt für --ros 1; eine ROS-2-Bridge nimmt --ros-domain</translation>
    </message>
    <message>
        <source>%1 of the failed were json payloads over %2 MiB, refused unread</source>
        <translation>%1 der fehlgeschlagenen waren JSON-Nutzdaten über %2 MiB, ungelesen abgelehnt</translation>
    </message>
</context>
<context>
    <name>BridgedTopicsProxy</name>
    <message>
        <source>Bridged: %1</source>
        <translation>Übertragen: %1</translation>
    </message>
</context>
<context>
    <name>Cli</name>
    <message>
        <source>Show this help.</source>
        <translation>Diese Hilfe anzeigen.</translation>
    </message>
    <message>
        <source>Run &apos;%1 --help&apos; for usage.</source>
        <translation>&apos;%1 --help&apos; zeigt die Verwendung.</translation>
    </message>
    <message>
        <source>error: cannot write to standard output: %1</source>
        <translation>Fehler: die Standardausgabe kann nicht geschrieben werden: %1</translation>
    </message>
    <message>
        <source>--seconds takes 0 to %1 seconds (a year)</source>
        <translation>--seconds erwartet 0 bis %1 Sekunden (ein Jahr)</translation>
    </message>
    <message>
        <source>%1: unknown option %2</source>
        <translation>%1: unbekannte Option %2</translation>
    </message>
    <message>
        <source>Did you mean %1?</source>
        <translation>Ist %1 gemeint?</translation>
    </message>
</context>
<context>
    <name>ClockCommand</name>
    <message>
        <source>--udp takes %1, not &apos;%2&apos;</source>
        <translation>--udp erwartet %1, nicht „%2“</translation>
    </message>
    <message>
        <source>--udp: cannot resolve &apos;%1&apos;: %2</source>
        <translation>--udp: „%1“ lässt sich nicht auflösen: %2</translation>
    </message>
    <message>
        <source>--broker: %1</source>
        <translation>--broker: %1</translation>
    </message>
    <message>
        <source>answered %1, malformed %2, refused %3, over budget %4, send failed %5</source>
        <translation>beantwortet %1, fehlerhaft %2, abgelehnt %3, über dem Budget %4, Senden fehlgeschlagen %5</translation>
    </message>
    <message>
        <source>This host&apos;s name, as pipelines name it (required).</source>
        <translation>Der Name dieses Rechners, wie Pipelines ihn nennen (erforderlich).</translation>
    </message>
    <message>
        <source>Answer probes through this broker.</source>
        <translation>Proben über diesen Broker beantworten.</translation>
    </message>
    <message>
        <source>Answer probes on this UDP port (address 127.0.0.1 unless given; port 0: a free one).</source>
        <translation>Proben auf diesem UDP-Port beantworten (Adresse 127.0.0.1, wenn keine angegeben ist; Port 0: ein freier).</translation>
    </message>
    <message>
        <source>Answer as a clock this many ms ahead (tests and demos).</source>
        <translation>Als Uhr antworten, die so viele ms vorgeht (Tests und Demos).</translation>
    </message>
    <message>
        <source>Answers four-timestamp clock probes from other hosts (bridgescope clock probe) over the broker on bridgescope/clock/NAME/probe and/or on a UDP port, with this host&apos;s sync state from chrony or linuxptp when it can read it. Runs until Ctrl+C or SIGTERM; prints its counts at the start and once a minute.
Exit status: 0 stopped, 1 the port or the broker failed, 2 bad options.</source>
        <translation>Beantwortet Uhrproben mit vier Zeitstempeln von anderen Rechnern (bridgescope clock probe) über den Broker auf bridgescope/clock/NAME/probe und/oder auf einem UDP-Port, mit dem Synchronisationszustand dieses Rechners von chrony oder linuxptp, wenn er lesbar ist. Läuft bis Strg+C oder SIGTERM; gibt seine Zählungen zu Beginn und einmal pro Minute aus.
Exit-Status: 0 beendet, 1 Port oder Broker fehlgeschlagen, 2 falsche Optionen.</translation>
    </message>
    <message>
        <source>--name takes 1 to 64 bytes without spaces, &apos;/&apos;, &apos;+&apos; or &apos;#&apos;; see bridgescope clock serve --help</source>
        <translation>--name erwartet 1 bis 64 Bytes ohne Leerzeichen, „/“, „+“ oder „#“; siehe bridgescope clock serve --help</translation>
    </message>
    <message>
        <source>--clock-offset-ms takes a number of ms within a day</source>
        <translation>--clock-offset-ms erwartet eine Zahl von ms innerhalb eines Tages</translation>
    </message>
    <message>
        <source>clock serve needs --udp, --broker or both; see bridgescope clock serve --help</source>
        <translation>clock serve braucht --udp, --broker oder beides; siehe bridgescope clock serve --help</translation>
    </message>
    <message>
        <source>UDP %1:%2</source>
        <translation>UDP %1:%2</translation>
    </message>
    <message>
        <source>MQTT %1 on %2</source>
        <translation>MQTT %1 auf %2</translation>
    </message>
    <message>
        <source>Clock service %1 (clock offset %2 ms): %3</source>
        <translation>Uhrdienst %1 (Uhrversatz %2 ms): %3</translation>
    </message>
    <message>
        <source>Sync state: %1</source>
        <translation>Synchronisationszustand: %1</translation>
    </message>
    <message>
        <source>MQTT: %1</source>
        <translation>MQTT: %1</translation>
    </message>
    <message>
        <source>Clock of %1</source>
        <translation>Uhr von %1</translation>
    </message>
    <message>
        <source>offset</source>
        <translation>Versatz</translation>
    </message>
    <message>
        <source>%1 ms ± %2 ms (far clock minus ours)</source>
        <translation>%1 ms ± %2 ms (ferne Uhr minus unsere)</translation>
    </message>
    <message>
        <source>drift</source>
        <translation>Drift</translation>
    </message>
    <message>
        <source>not measured (probes span under 10 s)</source>
        <translation>nicht gemessen (Proben umfassen weniger als 10 s)</translation>
    </message>
    <message>
        <source>%1 ppm</source>
        <translation>%1 ppm</translation>
    </message>
    <message>
        <source>best round trip</source>
        <translation>beste Umlaufzeit</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>probes</source>
        <translation>Proben</translation>
    </message>
    <message>
        <source>%1 sent, %2 answered, %3 lost, %4 unknown answers</source>
        <translation>%1 gesendet, %2 beantwortet, %3 verloren, %4 unbekannte Antworten</translation>
    </message>
    <message>
        <source>far sync state</source>
        <translation>ferne Synchronisation</translation>
    </message>
    <message>
        <source>Probe the clock service on this UDP address and port.</source>
        <translation>Den Uhrdienst auf dieser UDP-Adresse und diesem Port proben.</translation>
    </message>
    <message>
        <source>Probe through this broker (with --host).</source>
        <translation>Über diesen Broker proben (mit --host).</translation>
    </message>
    <message>
        <source>The far host&apos;s name (its clock serve --name).</source>
        <translation>Der Name des fernen Rechners (sein clock serve --name).</translation>
    </message>
    <message>
        <source>Probes to send (default 10; the first 8 in a burst).</source>
        <translation>Zu sendende Proben (Standard 10; die ersten 8 in einem Schub).</translation>
    </message>
    <message>
        <source>Between the probes after the burst (default 1000).</source>
        <translation>Abstand der Proben nach dem Schub (Standard 1000).</translation>
    </message>
    <message>
        <source>Print one JSON document.</source>
        <translation>Ein JSON-Dokument ausgeben.</translation>
    </message>
    <message>
        <source>Measures a far host&apos;s clock against ours with four-timestamp probes to its clock service (bridgescope clock serve): the offset (far minus ours) with the interval it surely lies in, the drift, the best round trip, and the far host&apos;s own sync state.
Exit status: 0 measured, 1 nothing answered, 2 bad options.</source>
        <translation>Misst die Uhr eines fernen Rechners gegen unsere mit Proben mit vier Zeitstempeln an seinen Uhrdienst (bridgescope clock serve): den Versatz (fern minus unsere) mit dem Intervall, in dem er sicher liegt, die Drift, die beste Umlaufzeit und den eigenen Synchronisationszustand des fernen Rechners.
Exit-Status: 0 gemessen, 1 nichts hat geantwortet, 2 falsche Optionen.</translation>
    </message>
    <message>
        <source>clock probe needs either --udp ADDR:PORT or --broker URL --host NAME</source>
        <translation>clock probe braucht entweder --udp ADRESSE:PORT oder --broker URL --host NAME</translation>
    </message>
    <message>
        <source>--host takes the far host&apos;s name: 1 to 64 bytes without spaces, &apos;/&apos;, &apos;+&apos; or &apos;#&apos;</source>
        <translation>--host erwartet den Namen des fernen Rechners: 1 bis 64 Bytes ohne Leerzeichen, „/“, „+“ oder „#“</translation>
    </message>
    <message>
        <source>--count takes 1 to 100000 probes, --interval-ms 10 to 3600000 ms</source>
        <translation>--count erwartet 1 bis 100000 Proben, --interval-ms 10 bis 3600000 ms</translation>
    </message>
    <message>
        <source>%1 on %2</source>
        <translation>%1 auf %2</translation>
    </message>
    <message>
        <source>Cannot probe %1: %2</source>
        <translation>%1 kann nicht geprobt werden: %2</translation>
    </message>
    <message>
        <source>Nothing answered the clock probes to %1 (%2 sent, %3 lost). Is &apos;bridgescope clock serve&apos; running there?</source>
        <translation>Niemand hat die Uhrproben an %1 beantwortet (%2 gesendet, %3 verloren). Läuft dort „bridgescope clock serve“?</translation>
    </message>
    <message>
        <source>Usage: bridgescope clock serve|probe [options]
  serve   answer clock probes on a UDP port and/or through a broker
  probe   measure a far host&apos;s clock against ours
See bridgescope clock serve --help and bridgescope clock probe --help.</source>
        <translation>Aufruf: bridgescope clock serve|probe [Optionen]
  serve   Uhrproben auf einem UDP-Port und/oder über einen Broker beantworten
  probe   die Uhr eines fernen Rechners gegen unsere messen
Siehe bridgescope clock serve --help und bridgescope clock probe --help.</translation>
    </message>
    <message>
        <source>clock takes serve or probe, not &apos;%1&apos;; see bridgescope clock --help</source>
        <translation>clock erwartet serve oder probe, nicht „%1“; siehe bridgescope clock --help</translation>
    </message>
    <message>
        <source>The last probe that could not be sent: %1</source>
        <translation>Die letzte Probe, die nicht gesendet werden konnte: %1</translation>
    </message>
</context>
<context>
    <name>ClockProbe</name>
    <message>
        <source>a clock probe has %1 bytes, not %2</source>
        <translation>eine Uhrprobe hat %1 Bytes, nicht %2</translation>
    </message>
    <message>
        <source>not a clock probe (wrong magic)</source>
        <translation>keine Uhrprobe (falsche Kennung)</translation>
    </message>
    <message>
        <source>clock probe version %1 is not known (%2 is)</source>
        <translation>Uhrproben-Version %1 ist unbekannt (bekannt ist %2)</translation>
    </message>
    <message>
        <source>clock probe kind %1 is not known</source>
        <translation>Uhrproben-Art %1 ist unbekannt</translation>
    </message>
    <message>
        <source>the host name of a clock probe is not valid</source>
        <translation>der Rechnername einer Uhrprobe ist ungültig</translation>
    </message>
    <message>
        <source>the reply topic of a clock probe is not valid</source>
        <translation>das Antwort-Topic einer Uhrprobe ist ungültig</translation>
    </message>
    <message>
        <source>a clock probe carries server fields</source>
        <translation>eine Uhrprobe enthält Serverfelder</translation>
    </message>
    <message>
        <source>a clock probe&apos;s answer lacks its host or has t3 before t2</source>
        <translation>der Antwort auf eine Uhrprobe fehlt der Rechner, oder t3 liegt vor t2</translation>
    </message>
    <message>
        <source>the sync state of a clock probe is not valid</source>
        <translation>der Synchronisationszustand einer Uhrprobe ist ungültig</translation>
    </message>
</context>
<context>
    <name>ClockServer</name>
    <message>
        <source>cannot listen for clock probes on UDP %1:%2: %3</source>
        <translation>auf UDP %1:%2 kann nicht auf Uhrproben gewartet werden: %3</translation>
    </message>
    <message>
        <source>&apos;%1&apos; cannot name a host (1 to 64 bytes without spaces, &apos;/&apos;, &apos;+&apos; or &apos;#&apos;)</source>
        <translation>„%1“ kann keinen Rechner benennen (1 bis 64 Bytes ohne Leerzeichen, „/“, „+“ oder „#“)</translation>
    </message>
</context>
<context>
    <name>ClockSync</name>
    <message>
        <source>chrony, %1 (%2): offset %3 ms, root delay %4 ms, root dispersion %5 ms, frequency %6 ppm</source>
        <translation>chrony, %1 (%2): Versatz %3 ms, Wurzelverzögerung %4 ms, Wurzelstreuung %5 ms, Frequenz %6 ppm</translation>
    </message>
    <message>
        <source>synchronised</source>
        <translation>synchronisiert</translation>
    </message>
    <message>
        <source>not synchronised</source>
        <translation>nicht synchronisiert</translation>
    </message>
    <message>
        <source>linuxptp, %1 (%2): master offset %3 ms</source>
        <translation>linuxptp, %1 (%2): Master-Versatz %3 ms</translation>
    </message>
    <message>
        <source>grandmaster present</source>
        <translation>Grandmaster vorhanden</translation>
    </message>
    <message>
        <source>no grandmaster</source>
        <translation>kein Grandmaster</translation>
    </message>
    <message>
        <source>not reported</source>
        <translation>nicht gemeldet</translation>
    </message>
</context>
<context>
    <name>ClockText</name>
    <message>
        <source>%1 %2 ms ± %3 ms against %4</source>
        <translation>%1 %2 ms ± %3 ms gegenüber %4</translation>
    </message>
</context>
<context>
    <name>ClockWatch</name>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>No clock service answers for %1 on the broker: run `bridgescope clock serve --name NAME --broker URL` on each host, or set one_clock: true for hosts that share a clock.</source>
        <translation>Für %1 antwortet kein Uhrendienst am Broker: `bridgescope clock serve --name NAME --broker URL` auf jedem Rechner starten oder one_clock: true setzen, wenn die Rechner eine Uhr teilen.</translation>
    </message>
    <message>
        <source>Clocks cannot be probed: %1.</source>
        <translation>Die Uhren lassen sich nicht abfragen: %1.</translation>
    </message>
    <message numerus="yes">
        <source>%n more host(s) not probed (at most %1).</source>
        <translation>
            <numerusform>%n weiterer Rechner nicht abgefragt (höchstens %1).</numerusform>
            <numerusform>%n weitere Rechner nicht abgefragt (höchstens %1).</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 for %2 s</source>
        <translation>%1 seit %2 s</translation>
    </message>
    <message>
        <source>No answer from the clock service of %1: the estimate kept grows less certain with time.</source>
        <translation>Keine Antwort vom Uhrendienst von %1: die behaltene Schätzung wird mit der Zeit unsicherer.</translation>
    </message>
</context>
<context>
    <name>ConfigCommand</name>
    <message>
        <source>%1: error: cannot read the file: %2</source>
        <translation>%1: error: Datei nicht lesbar: %2</translation>
    </message>
    <message>
        <source>%1: error: %2</source>
        <translation>%1: error: %2</translation>
    </message>
    <message>
        <source>Print errors only, no warnings.</source>
        <translation>Nur Fehler ausgeben, keine Warnungen.</translation>
    </message>
    <message>
        <source>Bridge configs (mqtt_client ROS 1/ROS 2, mqtt_bridge).</source>
        <translation>Bridge-Konfigurationen (mqtt_client ROS 1/ROS 2, mqtt_bridge).</translation>
    </message>
    <message>
        <source>Checks bridge configs. Prints FILE:LINE:COL: severity: message (fix) for each problem. Exit status: 0 all valid (warnings allowed), 1 some invalid, 2 some unreadable.</source>
        <translation>Prüft Bridge-Konfigurationen. Gibt je Problem DATEI:ZEILE:SPALTE: Schwere: Meldung (Abhilfe) aus. Exit-Status: 0 alle gültig (Warnungen erlaubt), 1 mindestens eine ungültig, 2 mindestens eine unlesbar.</translation>
    </message>
    <message>
        <source>bridgescope config validate: no FILE given</source>
        <translation>bridgescope config validate: keine DATEI angegeben</translation>
    </message>
    <message>
        <source>Layout to write: ros1, ros2 or mqtt_bridge.</source>
        <translation>Zu schreibendes Layout: ros1, ros2 oder mqtt_bridge.</translation>
    </message>
    <message>
        <source>Write to OUT instead of standard output.</source>
        <translation>Nach AUS statt auf die Standardausgabe schreiben.</translation>
    </message>
    <message>
        <source>ROS 2 node name above ros__parameters (default: as read, or mqtt_client).</source>
        <translation>ROS-2-Knotenname über ros__parameters (Vorgabe: wie gelesen, sonst mqtt_client).</translation>
    </message>
    <message>
        <source>The bridge config to convert.</source>
        <translation>Die zu konvertierende Bridge-Konfiguration.</translation>
    </message>
    <message>
        <source>Writes a bridge config in another layout; unknown keys, substitutions and values behind aliases are kept. An invalid config is refused (exit 1, its errors printed) unless --force.</source>
        <translation>Schreibt eine Bridge-Konfiguration in einem anderen Layout; unbekannte Schlüssel, Substitutionen und Werte hinter Aliasen bleiben erhalten. Eine ungültige Konfiguration wird abgelehnt (Status 1, ihre Fehler werden ausgegeben), außer mit --force.</translation>
    </message>
    <message>
        <source>Usage: bridgescope config convert FILE --to ros1|ros2|mqtt_bridge [-o OUT] [--force]</source>
        <translation>Aufruf: bridgescope config convert DATEI --to ros1|ros2|mqtt_bridge [-o AUS] [--force]</translation>
    </message>
    <message>
        <source>%1: note: %2</source>
        <translation>%1: note: %2</translation>
    </message>
    <message>
        <source>Client id of the peer (default: the id with &quot;_peer&quot; appended).</source>
        <translation>Client-ID der Gegenstelle (Vorgabe: die ID mit angehängtem &quot;_peer&quot;).</translation>
    </message>
    <message>
        <source>Layout to write (default: the input&apos;s).</source>
        <translation>Zu schreibendes Layout (Vorgabe: das der Eingabe).</translation>
    </message>
    <message>
        <source>This host&apos;s bridge config.</source>
        <translation>Die Bridge-Konfiguration dieses Rechners.</translation>
    </message>
    <message>
        <source>Writes the config for the other end of the link: every ros2mqtt becomes an mqtt2ros and the reverse. An invalid config is refused (exit 1, its errors printed) unless --force.</source>
        <translation>Schreibt die Konfiguration für das andere Ende der Strecke: aus jedem ros2mqtt wird ein mqtt2ros und umgekehrt. Eine ungültige Konfiguration wird abgelehnt (Status 1, ihre Fehler werden ausgegeben), außer mit --force.</translation>
    </message>
    <message>
        <source>Usage: bridgescope config peer FILE [-o OUT] [--client-id ID] [--force]</source>
        <translation>Aufruf: bridgescope config peer DATEI [-o AUS] [--client-id ID] [--force]</translation>
    </message>
    <message>
        <source>--to takes ros1, ros2 or mqtt_bridge</source>
        <translation>--to erwartet ros1, ros2 oder mqtt_bridge</translation>
    </message>
    <message>
        <source>bridgescope config: unknown command &apos;%1&apos;</source>
        <translation>bridgescope config: unbekannter Befehl &apos;%1&apos;</translation>
    </message>
    <message>
        <source>Write even an invalid config; what cannot be written is named on standard error.</source>
        <translation>Auch eine ungültige Konfiguration schreiben; was nicht geschrieben werden kann, wird auf der Standardfehlerausgabe genannt.</translation>
    </message>
    <message>
        <source>%1: error: the config is invalid; nothing was written (--force writes it anyway)</source>
        <translation>%1: Fehler: die Konfiguration ist ungültig; nichts wurde geschrieben (--force schreibt sie trotzdem)</translation>
    </message>
    <message>
        <source>%1: warning: %2</source>
        <translation>%1: Warnung: %2</translation>
    </message>
    <message>
        <source>&lt;stdout&gt;</source>
        <translation>&lt;Standardausgabe&gt;</translation>
    </message>
    <message>
        <source>Did you mean &apos;bridgescope config %1&apos;?</source>
        <translation>Ist &apos;bridgescope config %1&apos; gemeint?</translation>
    </message>
    <message>
        <source>Run &apos;bridgescope config --help&apos; for the commands.</source>
        <translation>&apos;bridgescope config --help&apos; nennt die Befehle.</translation>
    </message>
    <message>
        <source>Usage: bridgescope config &lt;command&gt; [options]

Commands:
  validate FILE... [--target RELEASE]      check bridge configs (against an mqtt_client release); exit 0 valid, 1 invalid, 2 unreadable
  convert FILE --to ros1|ros2|mqtt_bridge  write the config in another layout (a valid one, or --force)
  peer FILE [--client-id ID]               write the config for the other end of the link (a valid one, or --force)

Run &apos;bridgescope config &lt;command&gt; --help&apos; for the options of a command.</source>
        <translation>Aufruf: bridgescope config &lt;Befehl&gt; [Optionen]

Befehle:
  validate DATEI... [--target RELEASE]     Bridge-Konfigurationen prüfen (gegen ein Release von mqtt_client); Status 0 gültig, 1 ungültig, 2 unlesbar
  convert DATEI --to ros1|ros2|mqtt_bridge Konfiguration in einem anderen Layout schreiben (eine gültige, oder --force)
  peer DATEI [--client-id ID]              Konfiguration für das andere Ende der Strecke schreiben (eine gültige, oder --force)

&apos;bridgescope config &lt;Befehl&gt; --help&apos; zeigt die Optionen eines Befehls.</translation>
    </message>
    <message>
        <source>Check against this mqtt_client release: %1, or auto (the newest release that loads the file&apos;s layout, the default). Says which on a note line.</source>
        <translation>Gegen dieses Release von mqtt_client prüfen: %1, oder auto (das neueste Release, das das Layout der Datei lädt, die Vorgabe). Eine Hinweiszeile sagt, welches.</translation>
    </message>
    <message>
        <source>bridgescope config validate: --target &apos;%1&apos; is not a release of mqtt_client; use one of %2, or auto</source>
        <translation>bridgescope config validate: --target &apos;%1&apos; ist kein Release von mqtt_client; eines von %2 verwenden, oder auto</translation>
    </message>
</context>
<context>
    <name>ConfigDocument</name>
    <message>
        <source>Cannot open %1: %2</source>
        <translation>%1 lässt sich nicht öffnen: %2</translation>
    </message>
    <message>
        <source>%1 is not a bridge config.</source>
        <translation>%1 ist keine Bridge-Konfiguration.</translation>
    </message>
    <message>
        <source>this edit cannot be made in place (%1)</source>
        <translation>diese Änderung lässt sich nicht direkt in der Datei vornehmen (%1)</translation>
    </message>
    <message>
        <source>parts of the file could not be read and would be lost</source>
        <translation>Teile der Datei waren nicht lesbar und gingen verloren</translation>
    </message>
    <message>
        <source>the file is saved in another layout</source>
        <translation>die Datei wird in einem anderen Layout gespeichert</translation>
    </message>
    <message>
        <source>The file is not a bridge config.</source>
        <translation>Die Datei ist keine Bridge-Konfiguration.</translation>
    </message>
    <message>
        <source>%1 is open read-only: %2</source>
        <translation>%1 ist schreibgeschützt geöffnet: %2</translation>
    </message>
</context>
<context>
    <name>ConfigEditor</name>
    <message>
        <source>Edit topic</source>
        <translation>Topic bearbeiten</translation>
    </message>
    <message>
        <source>Add ROS → MQTT Mapping</source>
        <translation>Zuordnung ROS → MQTT hinzufügen</translation>
    </message>
    <message>
        <source>Bridge a ROS topic to MQTT (Insert)</source>
        <translation>Ein ROS-Topic nach MQTT übertragen (Einfg)</translation>
    </message>
    <message>
        <source>+ ROS → MQTT</source>
        <translation>+ ROS → MQTT</translation>
    </message>
    <message>
        <source>Add MQTT → ROS Mapping</source>
        <translation>Zuordnung MQTT → ROS hinzufügen</translation>
    </message>
    <message>
        <source>Bridge an MQTT topic to ROS (Shift+Insert)</source>
        <translation>Ein MQTT-Topic nach ROS übertragen (Umschalt+Einfg)</translation>
    </message>
    <message>
        <source>+ MQTT → ROS</source>
        <translation>+ MQTT → ROS</translation>
    </message>
    <message>
        <source>Delete Mappings</source>
        <translation>Zuordnungen löschen</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Löschen</translation>
    </message>
    <message>
        <source>Duplicate Mappings</source>
        <translation>Zuordnungen duplizieren</translation>
    </message>
    <message>
        <source>Filter mappings (topic or option)…</source>
        <translation>Zuordnungen filtern (Topic oder Option) …</translation>
    </message>
    <message>
        <source>Both directions</source>
        <translation>Beide Richtungen</translation>
    </message>
    <message>
        <source>With problems</source>
        <translation>Mit Problemen</translation>
    </message>
    <message>
        <source>&amp;Mapping</source>
        <translation>&amp;Zuordnung</translation>
    </message>
    <message>
        <source>&amp;Broker &amp;&amp; client</source>
        <translation>&amp;Broker und Client</translation>
    </message>
    <message>
        <source>&amp;YAML</source>
        <translation>&amp;YAML</translation>
    </message>
    <message>
        <source>Add ROS → MQTT mapping</source>
        <translation>Zuordnung ROS → MQTT hinzufügen</translation>
    </message>
    <message>
        <source>Add MQTT → ROS mapping</source>
        <translation>Zuordnung MQTT → ROS hinzufügen</translation>
    </message>
    <message>
        <source>Delete mapping</source>
        <translation>Zuordnung löschen</translation>
    </message>
    <message>
        <source>Delete %1 mappings</source>
        <translation>%1 Zuordnungen löschen</translation>
    </message>
    <message>
        <source>Duplicate mapping</source>
        <translation>Zuordnung duplizieren</translation>
    </message>
    <message>
        <source>Duplicate %1 mappings</source>
        <translation>%1 Zuordnungen duplizieren</translation>
    </message>
</context>
<context>
    <name>ConfigFileController</name>
    <message>
        <source>mqtt_client config, ROS 1 (*.yaml *.yml)</source>
        <translation>mqtt_client-Konfiguration, ROS 1 (*.yaml *.yml)</translation>
    </message>
    <message>
        <source>mqtt_client config, ROS 2 (*.yaml *.yml)</source>
        <translation>mqtt_client-Konfiguration, ROS 2 (*.yaml *.yml)</translation>
    </message>
    <message>
        <source>mqtt_bridge config (*.yaml *.yml)</source>
        <translation>mqtt_bridge-Konfiguration (*.yaml *.yml)</translation>
    </message>
    <message>
        <source>Cannot open the config</source>
        <translation>Konfiguration lässt sich nicht öffnen</translation>
    </message>
    <message>
        <source>Opened %1 (mappings: %2)</source>
        <translation>%1 geöffnet (Zuordnungen: %2)</translation>
    </message>
    <message>
        <source>The file cannot keep its comments and formatting: %1.

Saving writes it anew (the previous file stays as %2.bak). Save anyway?</source>
        <translation>Die Datei kann ihre Kommentare und Formatierung nicht behalten: %1.

Beim Speichern wird sie neu geschrieben (die vorige Datei bleibt als %2.bak erhalten). Trotzdem speichern?</translation>
    </message>
    <message>
        <source>Rewrite the file?</source>
        <translation>Datei neu schreiben?</translation>
    </message>
    <message>
        <source>Cannot save the config</source>
        <translation>Konfiguration lässt sich nicht speichern</translation>
    </message>
    <message>
        <source>Nothing was changed on disk: %1</source>
        <translation>Auf der Festplatte wurde nichts verändert: %1</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <source>Cannot export the config</source>
        <translation>Konfiguration lässt sich nicht exportieren</translation>
    </message>
    <message>
        <source>Exported %1 as %2%3</source>
        <translation>%1 als %2 exportiert%3</translation>
    </message>
    <message>
        <source>Cannot write the peer config</source>
        <translation>Gegenstellen-Konfiguration lässt sich nicht schreiben</translation>
    </message>
    <message>
        <source>Wrote the peer config %1%2</source>
        <translation>Gegenstellen-Konfiguration %1 geschrieben%2</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <source>Open Bridge Config</source>
        <translation>Bridge-Konfiguration öffnen</translation>
    </message>
    <message>
        <source>YAML files (*.yaml *.yml);;All files (*)</source>
        <translation>YAML-Dateien (*.yaml *.yml);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Save Bridge Config</source>
        <translation>Bridge-Konfiguration speichern</translation>
    </message>
    <message>
        <source>Export Bridge Config</source>
        <translation>Bridge-Konfiguration exportieren</translation>
    </message>
    <message>
        <source>Save Peer Config</source>
        <translation>Gegenstellen-Konfiguration speichern</translation>
    </message>
    <message>
        <source>Peer config written</source>
        <translation>Gegenstellen-Konfiguration geschrieben</translation>
    </message>
    <message>
        <source>Open the peer config %1 now?</source>
        <translation>Die Gegenstellen-Konfiguration %1 jetzt öffnen?</translation>
    </message>
    <message>
        <source>untitled</source>
        <translation>unbenannt</translation>
    </message>
    <message>
        <source>%1 has unsaved changes. Save them?</source>
        <translation>%1 hat ungespeicherte Änderungen. Speichern?</translation>
    </message>
    <message>
        <source>Opened %1 read-only: %2</source>
        <translation>%1 schreibgeschützt geöffnet: %2</translation>
    </message>
</context>
<context>
    <name>ConfigReader</name>
    <message>
        <source>&apos;%1&apos; must be a map of options, not a %2.</source>
        <translation>&apos;%1&apos; muss eine Map von Optionen sein, keine %2.</translation>
    </message>
    <message>
        <source>Write the options as &apos;key: value&apos; lines below &apos;%1&apos;.</source>
        <translation>Optionen als Zeilen &apos;schlüssel: wert&apos; unter &apos;%1&apos; schreiben.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; must be a single value, not a %2.</source>
        <translation>&apos;%1&apos; muss ein einzelner Wert sein, keine %2.</translation>
    </message>
    <message>
        <source>Write it as &apos;%1: value&apos;.</source>
        <translation>Als &apos;%1: wert&apos; schreiben.</translation>
    </message>
    <message>
        <source>map</source>
        <translation>Map</translation>
    </message>
    <message>
        <source>list</source>
        <translation>Liste</translation>
    </message>
    <message>
        <source>empty value</source>
        <translation>leerer Wert</translation>
    </message>
    <message>
        <source>single value</source>
        <translation>Einzelwert</translation>
    </message>
    <message>
        <source>&apos;bridge&apos; must be a map with &apos;ros2mqtt&apos; and &apos;mqtt2ros&apos; lists.</source>
        <translation>&apos;bridge&apos; muss eine Map mit den Listen &apos;ros2mqtt&apos; und &apos;mqtt2ros&apos; sein.</translation>
    </message>
    <message>
        <source>&apos;bridge.%1&apos; must be a list of mappings (&apos;- ros_topic: ...&apos;).</source>
        <translation>&apos;bridge.%1&apos; muss eine Liste von Zuordnungen sein (&apos;- ros_topic: ...&apos;).</translation>
    </message>
    <message>
        <source>This looks like the ROS 2 layout; it needs &apos;&lt;node&gt;: ros__parameters:&apos; around it, or write the mappings as a list.</source>
        <translation>Das sieht nach dem ROS-2-Layout aus; dann gehört &apos;&lt;knoten&gt;: ros__parameters:&apos; darum, sonst die Zuordnungen als Liste schreiben.</translation>
    </message>
    <message>
        <source>Entry %1 of &apos;bridge.%2&apos; must be a map with &apos;ros_topic&apos; and &apos;mqtt_topic&apos;.</source>
        <translation>Eintrag %1 von &apos;bridge.%2&apos; muss eine Map mit &apos;ros_topic&apos; und &apos;mqtt_topic&apos; sein.</translation>
    </message>
    <message>
        <source>&apos;bridge&apos; must be a map with &apos;ros2mqtt&apos; and &apos;mqtt2ros&apos;.</source>
        <translation>&apos;bridge&apos; muss eine Map mit &apos;ros2mqtt&apos; und &apos;mqtt2ros&apos; sein.</translation>
    </message>
    <message>
        <source>&apos;bridge.%1&apos; must be a map with &apos;%2&apos; and one entry per topic.</source>
        <translation>&apos;bridge.%1&apos; muss eine Map mit &apos;%2&apos; und einem Eintrag je Topic sein.</translation>
    </message>
    <message>
        <source>&apos;bridge.%1.%2&apos; must be a list of topic names.</source>
        <translation>&apos;bridge.%1.%2&apos; muss eine Liste von Topic-Namen sein.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is listed in &apos;%2&apos; but has no settings below &apos;bridge.%3&apos;.</source>
        <translation>&apos;%1&apos; steht in &apos;%2&apos;, hat aber keine Einstellungen unter &apos;bridge.%3&apos;.</translation>
    </message>
    <message>
        <source>Add &apos;%1:&apos; with its &apos;%2&apos; below &apos;bridge.%3&apos;.</source>
        <translation>&apos;%1:&apos; mit &apos;%2&apos; unter &apos;bridge.%3&apos; ergänzen.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; has settings below &apos;bridge.%2&apos; but is not listed in &apos;%3&apos;; mqtt_client ignores it.</source>
        <translation>&apos;%1&apos; hat Einstellungen unter &apos;bridge.%2&apos;, steht aber nicht in &apos;%3&apos;; mqtt_client ignoriert es.</translation>
    </message>
    <message>
        <source>Add &apos;%1&apos; to &apos;%2&apos; or remove its settings.</source>
        <translation>&apos;%1&apos; in &apos;%2&apos; aufnehmen oder seine Einstellungen entfernen.</translation>
    </message>
    <message>
        <source>mqtt_bridge&apos;s &apos;bridge&apos; must be a list of factories.</source>
        <translation>&apos;bridge&apos; von mqtt_bridge muss eine Liste von Factories sein.</translation>
    </message>
    <message>
        <source>Entry %1 of &apos;bridge&apos; must be a map with &apos;factory&apos;, &apos;msg_type&apos;, &apos;topic_from&apos; and &apos;topic_to&apos;.</source>
        <translation>Eintrag %1 von &apos;bridge&apos; muss eine Map mit &apos;factory&apos;, &apos;msg_type&apos;, &apos;topic_from&apos; und &apos;topic_to&apos; sein.</translation>
    </message>
    <message>
        <source>Entry %1 of &apos;bridge&apos; has factory &apos;%2&apos;; only mqtt_bridge&apos;s RosToMqttBridge and MqttToRosBridge are understood.</source>
        <translation>Eintrag %1 von &apos;bridge&apos; hat die Factory &apos;%2&apos;; verstanden werden nur RosToMqttBridge und MqttToRosBridge von mqtt_bridge.</translation>
    </message>
    <message>
        <source>YAML syntax error: %1</source>
        <translation>YAML-Syntaxfehler: %1</translation>
    </message>
    <message>
        <source>Fix the YAML at this place; nothing else could be checked.</source>
        <translation>YAML an dieser Stelle korrigieren; sonst ließ sich nichts prüfen.</translation>
    </message>
    <message>
        <source>The file is empty.</source>
        <translation>Die Datei ist leer.</translation>
    </message>
    <message>
        <source>The file is not a map; an mqtt_client config starts with &apos;broker:&apos;, &apos;client:&apos; and &apos;bridge:&apos; (or &apos;&lt;node&gt;: ros__parameters:&apos;).</source>
        <translation>Die Datei ist keine Map; eine mqtt_client-Konfiguration beginnt mit &apos;broker:&apos;, &apos;client:&apos; und &apos;bridge:&apos; (oder &apos;&lt;knoten&gt;: ros__parameters:&apos;).</translation>
    </message>
    <message>
        <source>&apos;ros__parameters&apos; must be a map.</source>
        <translation>&apos;ros__parameters&apos; muss eine Map sein.</translation>
    </message>
    <message>
        <source>This is not an mqtt_client or mqtt_bridge config: it has no &apos;bridge&apos;, &apos;broker&apos;, &apos;client&apos; or &apos;ros__parameters&apos; key.</source>
        <translation>Das ist keine mqtt_client- oder mqtt_bridge-Konfiguration: Es fehlt ein Schlüssel &apos;bridge&apos;, &apos;broker&apos;, &apos;client&apos; oder &apos;ros__parameters&apos;.</translation>
    </message>
    <message>
        <source>Open a bridge config; pipeline files belong on the Measure page.</source>
        <translation>Eine Bridge-Konfiguration öffnen; Pipeline-Dateien gehören auf die Seite Messen.</translation>
    </message>
    <message>
        <source>Unexpected YAML structure: %1</source>
        <translation>Unerwartete YAML-Struktur: %1</translation>
    </message>
    <message>
        <source>%1 is dropped when the config is written anew.</source>
        <translation>%1 geht verloren, wenn die Konfiguration neu geschrieben wird.</translation>
    </message>
    <message>
        <source>Entry %1 of &apos;bridge.%2&apos;</source>
        <translation>Eintrag %1 von &apos;bridge.%2&apos;</translation>
    </message>
    <message>
        <source>Entry %1 of &apos;bridge&apos;</source>
        <translation>Eintrag %1 von &apos;bridge&apos;</translation>
    </message>
    <message>
        <source>The rest of the file from this place on</source>
        <translation>Der Rest der Datei ab dieser Stelle</translation>
    </message>
    <message>
        <source>Split the file.</source>
        <translation>Teilen Sie die Datei auf.</translation>
    </message>
</context>
<context>
    <name>ConfigTabs</name>
    <message>
        <source>A config not saved yet</source>
        <translation>Eine noch nicht gespeicherte Konfiguration</translation>
    </message>
    <message>
        <source>Unsaved edits</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <source>%1 carry data</source>
        <translation>%1 übertragen Daten</translation>
    </message>
    <message>
        <source>%1 without a bridge</source>
        <translation>%1 ohne Brücke</translation>
    </message>
    <message>
        <source>%1 of another type</source>
        <translation>%1 eines anderen Typs</translation>
    </message>
    <message>
        <source>%1 whose QoS cannot match</source>
        <translation>%1, deren QoS nicht passen kann</translation>
    </message>
    <message>
        <source>%1 missing</source>
        <translation>%1 fehlen</translation>
    </message>
    <message>
        <source>%1 idle</source>
        <translation>%1 ruhen</translation>
    </message>
    <message>
        <source>%1 not seen yet</source>
        <translation>%1 noch nicht gesehen</translation>
    </message>
    <message numerus="yes">
        <source>%n mapping(s): %1</source>
        <translation>
            <numerusform>%n Zuordnung: %1</numerusform>
            <numerusform>%n Zuordnungen: %1</numerusform>
        </translation>
    </message>
    <message>
        <source>(read-only)</source>
        <translation>(schreibgeschützt)</translation>
    </message>
</context>
<context>
    <name>ConfigValidator</name>
    <message>
        <source>ros2mqtt &apos;%1&apos; → &apos;%2&apos;</source>
        <translation>ros2mqtt &apos;%1&apos; → &apos;%2&apos;</translation>
    </message>
    <message>
        <source>mqtt2ros &apos;%1&apos; → &apos;%2&apos;</source>
        <translation>mqtt2ros &apos;%1&apos; → &apos;%2&apos;</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is only understood by the ROS 2 mqtt_client (2.3 and later); the ROS 1 mqtt_client ignores it.</source>
        <translation>%1: &apos;%2&apos; versteht nur der ROS-2-mqtt_client (ab 2.3); der ROS-1-mqtt_client ignoriert es.</translation>
    </message>
    <message>
        <source>Remove &apos;%1&apos; or save the config in the ROS 2 layout.</source>
        <translation>&apos;%1&apos; entfernen oder die Konfiguration im ROS-2-Layout speichern.</translation>
    </message>
    <message>
        <source>%1: QoS &apos;%2&apos; is not 0, 1 or 2.</source>
        <translation>%1: QoS &apos;%2&apos; ist nicht 0, 1 oder 2.</translation>
    </message>
    <message>
        <source>Set %1 to 0 (at most once), 1 (at least once) or 2 (exactly once).</source>
        <translation>%1 auf 0 (höchstens einmal), 1 (mindestens einmal) oder 2 (genau einmal) setzen.</translation>
    </message>
    <message>
        <source>a whole number</source>
        <translation>eine ganze Zahl</translation>
    </message>
    <message>
        <source>a number</source>
        <translation>eine Zahl</translation>
    </message>
    <message>
        <source>true or false</source>
        <translation>true oder false</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is &apos;%3&apos;, which is not %4.</source>
        <translation>%1: &apos;%2&apos; ist &apos;%3&apos;, das ist nicht %4.</translation>
    </message>
    <message>
        <source>Write %1 as %2.</source>
        <translation>%1 als %2 schreiben.</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is %3, outside %4..%5.</source>
        <translation>%1: &apos;%2&apos; ist %3, außerhalb von %4..%5.</translation>
    </message>
    <message>
        <source>Choose a value from %1 to %2.</source>
        <translation>Einen Wert von %1 bis %2 wählen.</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; must not be negative.</source>
        <translation>%1: &apos;%2&apos; darf nicht negativ sein.</translation>
    </message>
    <message>
        <source>Use 0 or a positive number.</source>
        <translation>0 oder eine positive Zahl verwenden.</translation>
    </message>
    <message>
        <source>%1: &apos;%2: %3&apos; is read as a number or boolean, but mqtt_client expects text%4.</source>
        <translation>%1: &apos;%2: %3&apos; wird als Zahl oder Wahrheitswert gelesen, mqtt_client erwartet aber Text%4.</translation>
    </message>
    <message>
        <source> (ROS 2 rejects the parameter)</source>
        <translation> (ROS 2 lehnt den Parameter ab)</translation>
    </message>
    <message>
        <source>Quote it: %1: &quot;%2&quot;.</source>
        <translation>In Anführungszeichen setzen: %1: &quot;%2&quot;.</translation>
    </message>
    <message>
        <source>%1: unknown key &apos;%2&apos;; mqtt_client ignores it.</source>
        <translation>%1: unbekannter Schlüssel &apos;%2&apos;; mqtt_client ignoriert ihn.</translation>
    </message>
    <message>
        <source>Did you mean &apos;%1&apos;?</source>
        <translation>Ist &apos;%1&apos; gemeint?</translation>
    </message>
    <message>
        <source>%1 has no ROS topic; mqtt_client ignores the mapping.</source>
        <translation>%1 hat kein ROS-Topic; mqtt_client ignoriert die Zuordnung.</translation>
    </message>
    <message>
        <source>Set ros_topic, e.g. /vehicle/points.</source>
        <translation>ros_topic setzen, z. B. /vehicle/points.</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a valid ROS topic name: %3.</source>
        <translation>%1: &apos;%2&apos; ist kein gültiger ROS-Topic-Name: %3.</translation>
    </message>
    <message>
        <source>Use letters, digits, &apos;_&apos; and &apos;/&apos;, starting with a letter, &apos;/&apos; or &apos;~&apos;.</source>
        <translation>Buchstaben, Ziffern, &apos;_&apos; und &apos;/&apos; verwenden, beginnend mit Buchstabe, &apos;/&apos; oder &apos;~&apos;.</translation>
    </message>
    <message>
        <source>%1 has no MQTT topic; mqtt_client ignores the mapping.</source>
        <translation>%1 hat kein MQTT-Topic; mqtt_client ignoriert die Zuordnung.</translation>
    </message>
    <message>
        <source>Set mqtt_topic, e.g. vehicle/points.</source>
        <translation>mqtt_topic setzen, z. B. vehicle/points.</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; contains &apos;+&apos; or &apos;#&apos;, but ros2mqtt publishes on it and MQTT forbids wildcards in published topics.</source>
        <translation>%1: &apos;%2&apos; enthält &apos;+&apos; oder &apos;#&apos;, aber ros2mqtt veröffentlicht darauf, und MQTT verbietet Platzhalter in veröffentlichten Topics.</translation>
    </message>
    <message>
        <source>Replace the wildcard by a concrete topic level.</source>
        <translation>Den Platzhalter durch eine konkrete Topic-Ebene ersetzen.</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a valid MQTT topic: %3.</source>
        <translation>%1: &apos;%2&apos; ist kein gültiges MQTT-Topic: %3.</translation>
    </message>
    <message>
        <source>Fix the topic name.</source>
        <translation>Den Topic-Namen korrigieren.</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is a wildcard filter; mqtt_client looks incoming messages up by their exact topic, so messages matching it are dropped.</source>
        <translation>%1: &apos;%2&apos; ist ein Platzhalter-Filter; mqtt_client sucht eingehende Nachrichten über ihr genaues Topic, passende Nachrichten gehen daher verloren.</translation>
    </message>
    <message>
        <source>Bridge each MQTT topic with its own mqtt2ros mapping.</source>
        <translation>Jedes MQTT-Topic mit einer eigenen mqtt2ros-Zuordnung übertragen.</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; starts with &apos;/&apos;, which makes an empty first level in MQTT (a common slip when copying ROS names).</source>
        <translation>%1: &apos;%2&apos; beginnt mit &apos;/&apos;, das ergibt in MQTT eine leere erste Ebene (ein häufiges Versehen beim Kopieren von ROS-Namen).</translation>
    </message>
    <message>
        <source>Remove the leading &apos;/&apos;: &apos;%1&apos;.</source>
        <translation>Das führende &apos;/&apos; entfernen: &apos;%1&apos;.</translation>
    </message>
    <message>
        <source>%1: topics starting with &apos;$&apos; are reserved for the broker ($SYS).</source>
        <translation>%1: Topics, die mit &apos;$&apos; beginnen, sind dem Broker vorbehalten ($SYS).</translation>
    </message>
    <message>
        <source>Choose a topic that does not start with &apos;$&apos;.</source>
        <translation>Ein Topic wählen, das nicht mit &apos;$&apos; beginnt.</translation>
    </message>
    <message>
        <source>%1: inject_timestamp cannot be used with primitive: a primitive is sent as plain text with no room for a time stamp.</source>
        <translation>%1: inject_timestamp geht nicht mit primitive: Ein Primitivwert wird als reiner Text gesendet, ohne Platz für einen Zeitstempel.</translation>
    </message>
    <message>
        <source>Turn off primitive, or turn off inject_timestamp.</source>
        <translation>primitive oder inject_timestamp ausschalten.</translation>
    </message>
    <message>
        <source>%1: json needs ros_type: mqtt_client cannot build a ROS message from JSON without knowing its type.</source>
        <translation>%1: json braucht ros_type: Ohne den Typ kann mqtt_client aus JSON keine ROS-Nachricht bauen.</translation>
    </message>
    <message>
        <source>%1: json without ros_type: this side deduces the type from the publisher, but the receiving mqtt2ros needs it written down.</source>
        <translation>%1: json ohne ros_type: Diese Seite ermittelt den Typ vom Publisher, das empfangende mqtt2ros braucht ihn aber ausdrücklich.</translation>
    </message>
    <message>
        <source>Set ros_type, e.g. std_msgs/msg/String.</source>
        <translation>ros_type setzen, z. B. std_msgs/msg/String.</translation>
    </message>
    <message>
        <source>%1: json and primitive exclude each other.</source>
        <translation>%1: json und primitive schließen sich aus.</translation>
    </message>
    <message>
        <source>Turn one of them off.</source>
        <translation>Eines von beiden ausschalten.</translation>
    </message>
    <message>
        <source>%1: MQTT topic &apos;%2&apos; is already bridged by %3 (line %4); mqtt_client keeps only one of them.</source>
        <translation>%1: MQTT-Topic &apos;%2&apos; wird schon von %3 übertragen (Zeile %4); mqtt_client behält nur eine davon.</translation>
    </message>
    <message>
        <source>Remove one of the two mappings, or subscribe a different MQTT topic.</source>
        <translation>Eine der beiden Zuordnungen entfernen oder ein anderes MQTT-Topic abonnieren.</translation>
    </message>
    <message>
        <source>%1 and %2 form a loop: every message on &apos;%3&apos; goes to MQTT and comes back to &apos;%3&apos;.</source>
        <translation>%1 und %2 bilden eine Schleife: Jede Nachricht auf &apos;%3&apos; geht nach MQTT und kommt auf &apos;%3&apos; zurück.</translation>
    </message>
    <message>
        <source>Publish the returning messages on a different ROS topic.</source>
        <translation>Die zurückkommenden Nachrichten auf einem anderen ROS-Topic veröffentlichen.</translation>
    </message>
    <message>
        <source>%1.%2: &apos;%3&apos; does not exist on this machine (looked for %4).</source>
        <translation>%1.%2: &apos;%3&apos; gibt es auf diesem Rechner nicht (gesucht als %4).</translation>
    </message>
    <message>
        <source>Check the path on the machine that runs mqtt_client; relative paths are resolved against ROS_HOME.</source>
        <translation>Den Pfad auf dem Rechner prüfen, auf dem mqtt_client läuft; relative Pfade gelten ab ROS_HOME.</translation>
    </message>
    <message>
        <source>client.buffer is set but client.id is empty; mqtt_client only buffers for a client with an ID.</source>
        <translation>client.buffer ist gesetzt, client.id aber leer; mqtt_client puffert nur für einen Client mit ID.</translation>
    </message>
    <message>
        <source>Set client.id, e.g. vehicle.</source>
        <translation>client.id setzen, z. B. vehicle.</translation>
    </message>
    <message>
        <source>client.last_will.topic &apos;%1&apos; is not a topic the broker can publish on: %2.</source>
        <translation>client.last_will.topic &apos;%1&apos; ist kein Topic, auf dem der Broker veröffentlichen kann: %2.</translation>
    </message>
    <message>
        <source>Use a topic without &apos;+&apos; and &apos;#&apos;.</source>
        <translation>Ein Topic ohne &apos;+&apos; und &apos;#&apos; verwenden.</translation>
    </message>
    <message>
        <source>The config bridges nothing: it has no entries under &apos;bridge&apos; (fine for a settings fragment loaded beside the bridge list).</source>
        <translation>Die Konfiguration überträgt nichts: Unter &apos;bridge&apos; steht kein Eintrag (in Ordnung für ein Einstellungs-Fragment neben der Bridge-Liste).</translation>
    </message>
    <message>
        <source>The config bridges nothing: mqtt_client exits when it finds no ros2mqtt or mqtt2ros mapping.</source>
        <translation>Die Konfiguration überträgt nichts: mqtt_client beendet sich, wenn es keine ros2mqtt- oder mqtt2ros-Zuordnung findet.</translation>
    </message>
    <message>
        <source>Add a mapping.</source>
        <translation>Eine Zuordnung hinzufügen.</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is the roslaunch substitution %3, which ROS 2 parameter files do not substitute: the ROS 2 mqtt_client reads it as it stands.</source>
        <translation>%1: &apos;%2&apos; ist die roslaunch-Substitution %3, die ROS-2-Parameterdateien nicht ersetzen: der ROS-2-mqtt_client liest sie unverändert.</translation>
    </message>
    <message>
        <source>Write the value itself, or keep the config in the ROS 1 layout for roslaunch.</source>
        <translation>Den Wert selbst schreiben oder die Konfiguration für roslaunch im ROS-1-Layout lassen.</translation>
    </message>
    <message>
        <source>The config is in the ROS 1 layout, which mqtt_client loads only up to 2.3.0: %1 has no ROS 1 node (2.4.0 dropped ROS 1).</source>
        <translation>Die Konfiguration hat das ROS-1-Layout, das mqtt_client nur bis 2.3.0 lädt: %1 hat keinen ROS-1-Knoten (2.4.0 hat ROS 1 entfernt).</translation>
    </message>
    <message>
        <source>Convert it (bridgescope config convert FILE --to ros2), or target 2.3.</source>
        <translation>Umwandeln (bridgescope config convert DATEI --to ros2), oder 2.3 als Ziel wählen.</translation>
    </message>
    <message>
        <source>%1: mqtt_client bridges %2 as a primitive from 2.4.2 on; %3, the release this config targets, does not.</source>
        <translation>%1: mqtt_client überträgt %2 erst ab 2.4.2 als Primitive; %3, das Ziel-Release dieser Konfiguration, nicht.</translation>
    </message>
    <message>
        <source>Target mqtt_client 2.4.2 or later, or bridge it without primitive.</source>
        <translation>mqtt_client 2.4.2 oder neuer als Ziel wählen, oder ohne primitive übertragen.</translation>
    </message>
    <message>
        <source>%1: mqtt_client reads &apos;%2&apos; from %3 on; %4, the release this config targets, ignores it.</source>
        <translation>%1: mqtt_client liest &apos;%2&apos; erst ab %3; %4, das Ziel-Release dieser Konfiguration, ignoriert es.</translation>
    </message>
    <message>
        <source>Target mqtt_client %1 or later, or remove &apos;%2&apos;.</source>
        <translation>mqtt_client %1 oder neuer als Ziel wählen, oder &apos;%2&apos; entfernen.</translation>
    </message>
    <message>
        <source>%1: ROS topic &apos;%2&apos; is already bridged by %3 (line %4); mqtt_client keeps one bridge per ROS topic, so only one of the two MQTT topics is published (mqtt_client issue #18).</source>
        <translation>%1: Das ROS-Topic &apos;%2&apos; wird schon von %3 (Zeile %4) übertragen; mqtt_client hält eine Bridge je ROS-Topic, also wird nur eines der beiden MQTT-Topics veröffentlicht (mqtt_client-Issue #18).</translation>
    </message>
    <message>
        <source>Remove one of the two mappings. To publish one ROS topic on two MQTT topics, relay it to a second ROS topic (topic_tools relay) and bridge that one.</source>
        <translation>Eine der beiden Zuordnungen entfernen. Um ein ROS-Topic auf zwei MQTT-Topics zu veröffentlichen, es auf ein zweites ROS-Topic weiterleiten (topic_tools relay) und dieses übertragen.</translation>
    </message>
</context>
<context>
    <name>ConfigWriter</name>
    <message>
        <source>%1: &apos;%2&apos; is bridged twice; the ROS 2 layout keys mappings by topic, so only the last one is written.</source>
        <translation>%1: &apos;%2&apos; wird doppelt übertragen; das ROS-2-Layout ordnet Zuordnungen nach Topic, daher wird nur die letzte geschrieben.</translation>
    </message>
    <message>
        <source>client.%1 has no equivalent in mqtt_bridge and is not written.</source>
        <translation>client.%1 hat in mqtt_bridge keine Entsprechung und wird nicht geschrieben.</translation>
    </message>
    <message>
        <source>%1: mqtt_bridge needs the message type; set ros_type (written as %2).</source>
        <translation>%1: mqtt_bridge braucht den Nachrichtentyp; ros_type setzen (geschrieben als %2).</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; has no equivalent in mqtt_bridge and is not written.</source>
        <translation>%1: &apos;%2&apos; hat in mqtt_bridge keine Entsprechung und wird nicht geschrieben.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; has no place in the written config and is dropped.</source>
        <translation>&apos;%1&apos; hat in der geschriebenen Konfiguration keinen Platz und geht verloren.</translation>
    </message>
</context>
<context>
    <name>DdsChildServer</name>
    <message>
        <source>a request of kind %1 does not read</source>
        <translation>eine Anfrage der Art %1 ist nicht lesbar</translation>
    </message>
    <message>
        <source>Cyclone DDS refused it</source>
        <translation>Cyclone DDS hat sie abgelehnt</translation>
    </message>
</context>
<context>
    <name>DemoCommand</name>
    <message>
        <source>Keep the recording as this run file.</source>
        <translation>Die Aufzeichnung als diese Laufdatei behalten.</translation>
    </message>
    <message>
        <source>Summary at the end: md (default) or json.</source>
        <translation>Zusammenfassung am Ende: md (Vorgabe) oder json.</translation>
    </message>
    <message>
        <source>Point cloud size in bytes (default 180000).</source>
        <translation>Größe der Punktwolke in Bytes (Vorgabe 180000).</translation>
    </message>
    <message>
        <source>--format takes md or json</source>
        <translation>--format erwartet md oder json</translation>
    </message>
    <message>
        <source>--size takes a number of bytes (at least 16)</source>
        <translation>--size erwartet eine Anzahl Bytes (mindestens 16)</translation>
    </message>
    <message>
        <source>%1 exists already; a run is never overwritten</source>
        <translation>%1 existiert bereits; ein Lauf wird nie überschrieben</translation>
    </message>
    <message>
        <source>starting the demo lab…</source>
        <translation>starte das Demo-Labor …</translation>
    </message>
    <message>
        <source>the demo lab did not start: %1</source>
        <translation>das Demo-Labor ist nicht gestartet: %1</translation>
    </message>
    <message>
        <source>broker %1, ROS master %2, configs in %3</source>
        <translation>Broker %1, ROS-Master %2, Konfigurationen in %3</translation>
    </message>
    <message>
        <source>demo lab</source>
        <translation>Demo-Labor</translation>
    </message>
    <message>
        <source>bridgescope demo: %1 bytes at %2 Hz</source>
        <translation>bridgescope demo: %1 Bytes mit %2 Hz</translation>
    </message>
    <message>
        <source>the demo lab failed: %1</source>
        <translation>das Demo-Labor ist ausgefallen: %1</translation>
    </message>
    <message>
        <source>%1 s: %2 complete samples, total latency mean %3 ms</source>
        <translation>%1 s: %2 vollständige Proben, Gesamtlatenz im Mittel %3 ms</translation>
    </message>
    <message>
        <source>recording failed: %1</source>
        <translation>Aufzeichnung fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>the run is in %1</source>
        <translation>der Lauf liegt in %1</translation>
    </message>
    <message>
        <source>ROS master URI (default $ROS_MASTER_URI).</source>
        <translation>ROS-Master-URI (Vorgabe $ROS_MASTER_URI).</translation>
    </message>
    <message>
        <source>vehicle: point cloud size in bytes.</source>
        <translation>vehicle: Größe der Punktwolke in Bytes.</translation>
    </message>
    <message>
        <source>cloud: mean detection time.</source>
        <translation>cloud: mittlere Erkennungsdauer.</translation>
    </message>
    <message>
        <source>This host&apos;s clock error.</source>
        <translation>Abweichung der Uhr dieses Rechners.</translation>
    </message>
    <message>
        <source>vehicle or cloud.</source>
        <translation>vehicle oder cloud.</translation>
    </message>
    <message>
        <source>One of the demo lab&apos;s ROS nodes; the lab starts them.</source>
        <translation>Einer der ROS-Knoten des Demo-Labors; das Labor startet sie.</translation>
    </message>
    <message>
        <source>demo-node takes vehicle or cloud</source>
        <translation>demo-node erwartet vehicle oder cloud</translation>
    </message>
    <message>
        <source>demo-node %1: %2</source>
        <translation>demo-node %1: %2</translation>
    </message>
    <message>
        <source>Run for N seconds (default: until Ctrl+C).</source>
        <translation>N Sekunden laufen (Vorgabe: bis Strg+C).</translation>
    </message>
    <message>
        <source>vehicle: point clouds per second.</source>
        <translation>vehicle: Punktwolken je Sekunde.</translation>
    </message>
    <message>
        <source>Use this broker instead of a private mosquitto.</source>
        <translation>Diesen Broker statt eines eigenen mosquitto verwenden.</translation>
    </message>
    <message>
        <source>Use this ROS master instead of a private rosmaster.</source>
        <translation>Diesen ROS-Master statt eines eigenen rosmaster verwenden.</translation>
    </message>
    <message>
        <source>--ros takes 1 or 2</source>
        <translation>--ros nimmt 1 oder 2</translation>
    </message>
    <message>
        <source>--ros-domain takes a domain id from 0 to %1</source>
        <translation>--ros-domain erwartet eine Domänen-ID von 0 bis %1</translation>
    </message>
    <message>
        <source>1: ROS 1 nodes around a private rosmaster (default); 2: DDS nodes and ROS 2 bridges on a free private domain on 127.0.0.1.</source>
        <translation>1: ROS-1-Knoten um einen eigenen rosmaster (Standard); 2: DDS-Knoten und ROS-2-Brücken in einer freien eigenen Domain auf 127.0.0.1.</translation>
    </message>
    <message>
        <source>With --ros 2: this domain instead of a free one.</source>
        <translation>Mit --ros 2: diese Domain statt einer freien.</translation>
    </message>
    <message>
        <source>broker %1, ROS 2 domain %2 (this host only), configs in %3</source>
        <translation>Broker %1, ROS-2-Domain %2 (nur dieser Rechner), Konfigurationen in %3</translation>
    </message>
    <message>
        <source>1: a ROS 1 node (default); 2: a ROS 2 node over DDS.</source>
        <translation>1: ein ROS-1-Knoten (Standard); 2: ein ROS-2-Knoten über DDS.</translation>
    </message>
    <message>
        <source>ROS 2 domain id (default 0).</source>
        <translation>ROS-2-Domain-ID (Standard 0).</translation>
    </message>
    <message>
        <source>With --cloud-host: bridgescope&apos;s path there (default: this one&apos;s).</source>
        <translation>Mit --cloud-host: der Pfad von bridgescope dort (Vorgabe: der hiesige).</translation>
    </message>
    <message>
        <source>Runs the demo lab without a window: a private mosquitto and rosmaster, a vehicle and a cloud reference bridge, a 0.18 MB point cloud at 10 Hz, a 40 ms object detection in the cloud whose clock is 35 ms ahead, and stamps at every component; records every stamp and prints the latency report at the end. Everything it started stops with it, on this host and on the cloud&apos;s (--cloud-host).
Exit status: 0 samples measured, 1 the lab failed or measured nothing, 2 bad options.</source>
        <translation>Führt das Demo-Labor ohne Fenster aus: eigene Instanzen von mosquitto und rosmaster, je eine Referenz-Bridge im Fahrzeug und in der Cloud, eine Punktwolke von 0,18 MB mit 10 Hz, eine Objekterkennung von 40 ms in der Cloud, deren Uhr 35 ms vorgeht, und Zeitstempel an jeder Komponente; zeichnet jeden Zeitstempel auf und gibt am Ende den Latenzbericht aus. Alles, was es gestartet hat, endet mit ihm, auf diesem Rechner und auf dem der Cloud (--cloud-host).
Exit-Status: 0 Proben gemessen, 1 Labor ausgefallen oder nichts gemessen, 2 falsche Optionen.</translation>
    </message>
    <message>
        <source>--cloud-host: %1</source>
        <translation>--cloud-host: %1</translation>
    </message>
    <message>
        <source>--cloud-program needs --cloud-host</source>
        <translation>--cloud-program braucht --cloud-host</translation>
    </message>
    <message>
        <source>the cloud&apos;s side runs on %1, reaching this host at %2</source>
        <translation>die Seite der Cloud läuft auf %1 und erreicht diesen Rechner unter %2</translation>
    </message>
    <message>
        <source>Run the cloud&apos;s bridge, object detection and clock service on this host over OpenSSH (ssh://user@host[:port]; keys or an agent, never a password).</source>
        <translation>Bridge, Objekterkennung und Uhrendienst der Cloud über OpenSSH auf diesem Rechner ausführen (ssh://benutzer@rechner[:port]; Schlüssel oder ein Agent, nie ein Passwort).</translation>
    </message>
    <message>
        <source>broker %1, ROS 2 domain %2, configs in %3</source>
        <translation>Broker %1, ROS-2-Domäne %2, Konfigurationen in %3</translation>
    </message>
</context>
<context>
    <name>DemoLab</name>
    <message>
        <source>cannot make a folder for the demo: %1</source>
        <translation>Ordner für die Demo lässt sich nicht anlegen: %1</translation>
    </message>
    <message>
        <source>cannot write %1</source>
        <translation>%1 lässt sich nicht schreiben</translation>
    </message>
    <message>
        <source>%1 did not start: %2</source>
        <translation>%1 ist nicht gestartet: %2</translation>
    </message>
    <message>
        <source>cannot start %1: %2</source>
        <translation>%1 lässt sich nicht starten: %2</translation>
    </message>
    <message>
        <source>%1 stopped: %2</source>
        <translation>%1 hat sich beendet: %2</translation>
    </message>
    <message>
        <source>the demo needs mosquitto (scripts/setup.sh installs it) or --broker</source>
        <translation>die Demo braucht mosquitto (scripts/setup.sh installiert es) oder --broker</translation>
    </message>
    <message>
        <source>the demo needs rosmaster (scripts/setup.sh installs it) or --ros-master</source>
        <translation>die Demo braucht rosmaster (scripts/setup.sh installiert ihn) oder --ros-master</translation>
    </message>
    <message>
        <source>TLS needs %1 in %2</source>
        <translation>TLS braucht %1 in %2</translation>
    </message>
    <message>
        <source>the broker URL is too long</source>
        <translation>die Broker-URL ist zu lang</translation>
    </message>
    <message>
        <source>cannot make a pipe: %1</source>
        <translation>kann keine Pipe anlegen: %1</translation>
    </message>
    <message>
        <source>cannot write to a pipe: %1</source>
        <translation>kann nicht in eine Pipe schreiben: %1</translation>
    </message>
    <message>
        <source>no free ROS 2 domain on this host</source>
        <translation>keine freie ROS-2-Domain auf diesem Rechner</translation>
    </message>
    <message>
        <source>%1 (%2) does not say its ssh connection (SSH_CONNECTION)</source>
        <translation>%1 (%2) nennt seine ssh-Verbindung nicht (SSH_CONNECTION)</translation>
    </message>
    <message>
        <source>%1 (%2) made no folder for the lab</source>
        <translation>%1 (%2) hat keinen Ordner für das Labor angelegt</translation>
    </message>
    <message>
        <source>%1 did not start on %2: %3</source>
        <translation>%1 ist auf %2 nicht gestartet: %3</translation>
    </message>
    <message>
        <source>no answer</source>
        <translation>keine Antwort</translation>
    </message>
    <message>
        <source>a side on another host needs a broker without TLS or credentials in this version: they would have to be copied there</source>
        <translation>eine Seite auf einem anderen Rechner braucht in dieser Version einen Broker ohne TLS und Zugangsdaten: sie müssten dorthin kopiert werden</translation>
    </message>
    <message>
        <source>a side on another host runs the reference bridge: a bridge command runs on this host only</source>
        <translation>eine Seite auf einem anderen Rechner führt die Referenz-Bridge aus: ein Bridge-Befehl läuft nur auf diesem Rechner</translation>
    </message>
    <message>
        <source>%1 on %2 stopped: %3</source>
        <translation>%1 auf %2 beendet: %3</translation>
    </message>
</context>
<context>
    <name>DetailPane</name>
    <message>
        <source>%1 bytes: %2%3</source>
        <translation>%1 Bytes: %2%3</translation>
    </message>
    <message>
        <source>%1 elements%2</source>
        <translation>%1 Elemente%2</translation>
    </message>
    <message>
        <source>, first %1 shown</source>
        <translation>, die ersten %1 gezeigt</translation>
    </message>
    <message>
        <source>%1 elements</source>
        <translation>%1 Elemente</translation>
    </message>
    <message>
        <source>Select a ROS or MQTT topic to see what it carries.</source>
        <translation>Ein ROS- oder MQTT-Topic auswählen, um zu sehen, was es trägt.</translation>
    </message>
    <message>
        <source>Field</source>
        <translation>Feld</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Typ</translation>
    </message>
    <message>
        <source>&amp;Fields</source>
        <translation>&amp;Felder</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>Automatisch</translation>
    </message>
    <message>
        <source>Text</source>
        <translation>Text</translation>
    </message>
    <message>
        <source>JSON</source>
        <translation>JSON</translation>
    </message>
    <message>
        <source>Hex</source>
        <translation>Hex</translation>
    </message>
    <message>
        <source>&amp;Show as:</source>
        <translation>&amp;Anzeigen als:</translation>
    </message>
    <message>
        <source>&amp;Payload</source>
        <translation>&amp;Nutzdaten</translation>
    </message>
    <message>
        <source>Received</source>
        <translation>Empfangen</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>Größe</translation>
    </message>
    <message>
        <source>Retained</source>
        <translation>Retained</translation>
    </message>
    <message>
        <source>&amp;History</source>
        <translation>&amp;Verlauf</translation>
    </message>
    <message>
        <source>&amp;Rate</source>
        <translation>&amp;Rate</translation>
    </message>
    <message>
        <source>$SYS topic</source>
        <translation>$SYS-Topic</translation>
    </message>
    <message>
        <source>&amp;Broker</source>
        <translation>&amp;Broker</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;: a level of the topic tree; select a topic below it.</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;: eine Ebene des Topic-Baums; ein Topic darunter auswählen.</translation>
    </message>
    <message>
        <source>(no messages on this level itself)</source>
        <translation>(keine Nachrichten auf dieser Ebene selbst)</translation>
    </message>
    <message>
        <source>%1 messages, %2, last %3, QoS %4%5</source>
        <translation>%1 Nachrichten, %2, zuletzt %3, QoS %4%5</translation>
    </message>
    <message>
        <source>, retained</source>
        <translation>, retained</translation>
    </message>
    <message>
        <source>ROS type %1 (announced by mqtt_client)%2</source>
        <translation>ROS-Typ %1 (von mqtt_client angekündigt)%2</translation>
    </message>
    <message>
        <source>, stamped</source>
        <translation>, mit Zeitstempel</translation>
    </message>
    <message>
        <source>one-way latency %1 ms (mean of the last %2: %3 ms); valid only as far as the sender&apos;s clock agrees with this one</source>
        <translation>Einweg-Latenz %1 ms (Mittel der letzten %2: %3 ms); nur so genau, wie die Uhr des Senders mit dieser übereinstimmt</translation>
    </message>
    <message>
        <source>%1 payloads did not decode as the announced type</source>
        <translation>%1 Nutzdaten ließen sich nicht als der angekündigte Typ dekodieren</translation>
    </message>
    <message>
        <source>malformed type announcement: %1</source>
        <translation>fehlerhafte Typankündigung: %1</translation>
    </message>
    <message>
        <source>does not decode as %1: %2</source>
        <translation>lässt sich nicht als %1 dekodieren: %2</translation>
    </message>
    <message>
        <source>(no structure known: see Payload)</source>
        <translation>(keine Struktur bekannt: siehe Nutzdaten)</translation>
    </message>
    <message>
        <source>retained</source>
        <translation>retained</translation>
    </message>
    <message>
        <source>msg/s</source>
        <translation>Nachr./s</translation>
    </message>
    <message>
        <source>Hz</source>
        <translation>Hz</translation>
    </message>
    <message>
        <source>%1; publishers: %2; subscribers: %3</source>
        <translation>%1; Publisher: %2; Subscriber: %3</translation>
    </message>
    <message>
        <source>Check Monitor to subscribe and see its messages.</source>
        <translation>Mon ankreuzen, um es zu abonnieren und seine Nachrichten zu sehen.</translation>
    </message>
    <message>
        <source>(not monitored)</source>
        <translation>(nicht beobachtet)</translation>
    </message>
    <message>
        <source>%1 messages, %2 Hz, %3/s, last %4</source>
        <translation>%1 Nachrichten, %2 Hz, %3/s, zuletzt %4</translation>
    </message>
    <message>
        <source>(waiting for the first message)</source>
        <translation>(warte auf die erste Nachricht)</translation>
    </message>
    <message>
        <source>Turn on $SYS in the connection profile to see the broker&apos;s figures.</source>
        <translation>$SYS im Verbindungsprofil einschalten, um die Kennzahlen des Brokers zu sehen.</translation>
    </message>
    <message>
        <source>&amp;Plot Field</source>
        <translation>Feld &amp;plotten</translation>
    </message>
    <message>
        <source>P&amp;lot</source>
        <translation>P&amp;lot</translation>
    </message>
    <message>
        <source>Plot the selected numeric field over time (Ctrl+L)</source>
        <translation>Das gewählte Zahlenfeld über der Zeit plotten (Strg+L)</translation>
    </message>
    <message>
        <source>Stop plotting the selected field (Del in the list)</source>
        <translation>Das gewählte Feld nicht mehr plotten (Entf in der Liste)</translation>
    </message>
    <message>
        <source>Clear &amp;All</source>
        <translation>Alle en&amp;tfernen</translation>
    </message>
    <message>
        <source>At most %1 fields are plotted at once.</source>
        <translation>Höchstens %1 Felder werden gleichzeitig geplottet.</translation>
    </message>
    <message>
        <source>%1 (%2 messages without a value: %3)</source>
        <translation>%1 (%2 Nachrichten ohne Wert: %3)</translation>
    </message>
    <message>
        <source>Select a number in Fields and press Ctrl+L (or Plot Field in its context menu).</source>
        <translation>Eine Zahl unter Felder wählen und Strg+L drücken (oder Feld plotten im Kontextmenü).</translation>
    </message>
    <message>
        <source>%1 messages not decoded to keep up (at most %2 per topic and tick are).</source>
        <translation>%1 Nachrichten nicht dekodiert, um Schritt zu halten (höchstens %2 je Topic und Takt werden es).</translation>
    </message>
    <message>
        <source>Remo&amp;ve</source>
        <translation>&amp;Entfernen</translation>
    </message>
    <message numerus="yes">
        <source>No ROS 2 definition of %1 is known: the payload shows its %n byte(s) raw.</source>
        <translation>
            <numerusform>Für %1 ist keine ROS-2-Definition bekannt: die Nutzdaten zeigen sein %n Byte roh.</numerusform>
            <numerusform>Für %1 ist keine ROS-2-Definition bekannt: die Nutzdaten zeigen seine %n Bytes roh.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 lost</source>
        <translation>%1 verloren</translation>
    </message>
    <message>
        <source>ROS 2 type %1 (announced by mqtt_client)%2</source>
        <translation>ROS-2-Typ %1 (von mqtt_client angekündigt)%2</translation>
    </message>
    <message numerus="yes">
        <source>%n more not shown</source>
        <translation>
            <numerusform>%n weiteres nicht angezeigt</numerusform>
            <numerusform>%n weitere nicht angezeigt</numerusform>
        </translation>
    </message>
    <message>
        <source>at most %1 fields are shown</source>
        <translation>höchstens %1 Felder werden angezeigt</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>&amp;Keep the last</source>
        <translation>&amp;Behalten: die letzten</translation>
    </message>
    <message>
        <source>and at &amp;most</source>
        <translation>und &amp;höchstens</translation>
    </message>
    <message>
        <source>points per field (%L1 at most: %2 MiB for %3 fields)</source>
        <translation>Punkte je Feld (höchstens %L1: %2 MiB für %3 Felder)</translation>
    </message>
    <message>
        <source>%1 ms old when it came (median of the last %2, by the DDS source timestamp: the writer&apos;s clock, true as far as it agrees with this one)</source>
        <translation>%1 ms alt beim Eintreffen (Median der letzten %2, nach dem DDS-Quellzeitstempel: der Uhr des Schreibers, so genau, wie sie mit dieser übereinstimmt)</translation>
    </message>
</context>
<context>
    <name>DiscoverCommand</name>
    <message>
        <source>ROS master %1: %2</source>
        <translation>ROS-Master %1: %2</translation>
    </message>
    <message>
        <source>reachable</source>
        <translation>erreichbar</translation>
    </message>
    <message>
        <source>unreachable (%1)</source>
        <translation>nicht erreichbar (%1)</translation>
    </message>
    <message>
        <source>MQTT broker %1: %2</source>
        <translation>MQTT-Broker %1: %2</translation>
    </message>
    <message>
        <source>connected</source>
        <translation>verbunden</translation>
    </message>
    <message>
        <source>not connected (%1)</source>
        <translation>nicht verbunden (%1)</translation>
    </message>
    <message>
        <source>  retained</source>
        <translation>  retained</translation>
    </message>
    <message>
        <source>Lists what is on the ROS master and the MQTT broker after listening for a while. Exit status: 0 when at least one of them answered, 1 when neither did, 2 on bad options.</source>
        <translation>Listet auf, was es beim ROS-Master und beim MQTT-Broker gibt, nachdem eine Weile zugehört wurde. Exit-Status: 0, wenn mindestens einer antwortete, 1, wenn keiner antwortete, 2 bei falschen Optionen.</translation>
    </message>
    <message>
        <source>Broker URL (default tcp://localhost:1883).</source>
        <translation>Broker-URL (Vorgabe tcp://localhost:1883).</translation>
    </message>
    <message>
        <source>ROS master URI (default $ROS_MASTER_URI).</source>
        <translation>ROS-Master-URI (Vorgabe $ROS_MASTER_URI).</translation>
    </message>
    <message>
        <source>How long to listen (default 2).</source>
        <translation>Wie lange zuhören (Vorgabe 2).</translation>
    </message>
    <message>
        <source>Print one JSON document.</source>
        <translation>Ein JSON-Dokument ausgeben.</translation>
    </message>
    <message>
        <source>MQTT topic filter to subscribe (default #; repeatable).</source>
        <translation>Zu abonnierender MQTT-Topic-Filter (Vorgabe #; mehrfach möglich).</translation>
    </message>
    <message>
        <source>Neither the ROS master (%1) nor the MQTT broker (%2) could be reached.</source>
        <translation>Weder der ROS-Master (%1) noch der MQTT-Broker (%2) war erreichbar.</translation>
    </message>
    <message>
        <source>ROS 2 domain %1: %2</source>
        <translation>ROS-2-Domäne %1: %2</translation>
    </message>
    <message>
        <source>ROS 2 domain %1: participants %2, topics %3, nodes %4</source>
        <translation>ROS-2-Domäne %1: Teilnehmer %2, Topics %3, Knoten %4</translation>
    </message>
    <message>
        <source>no participant</source>
        <translation>kein Teilnehmer</translation>
    </message>
    <message>
        <source>No ROS 2 participant answered on domain %1 and the MQTT broker (%2) could not be reached.</source>
        <translation>Auf Domäne %1 hat kein ROS-2-Teilnehmer geantwortet, und der MQTT-Broker (%2) war nicht erreichbar.</translation>
    </message>
    <message>
        <source>--seconds takes a positive number up to a year</source>
        <translation>--seconds erwartet eine positive Zahl bis zu einem Jahr</translation>
    </message>
    <message>
        <source>not complete: %1 messages on topics not kept (budget %2 topics, %3 MiB of names); %4 topics listed</source>
        <translation>nicht vollständig: %1 Nachrichten auf nicht behaltenen Topics (Budget %2 Topics, %3 MiB Namen); %4 Topics aufgeführt</translation>
    </message>
</context>
<context>
    <name>DiscoverPage</name>
    <message>
        <source>ROS master URI; Enter applies it</source>
        <translation>ROS-Master-URI; Eingabetaste übernimmt sie</translation>
    </message>
    <message>
        <source>ROS &amp;master:</source>
        <translation>ROS-&amp;Master:</translation>
    </message>
    <message>
        <source>MQTT &amp;broker:</source>
        <translation>MQTT-&amp;Broker:</translation>
    </message>
    <message>
        <source>Edit…</source>
        <translation>Bearbeiten …</translation>
    </message>
    <message>
        <source>Edit the connection profile (URL, TLS, credentials, subscriptions)</source>
        <translation>Das Verbindungsprofil bearbeiten (URL, TLS, Zugangsdaten, Abonnements)</translation>
    </message>
    <message>
        <source>New…</source>
        <translation>Neu …</translation>
    </message>
    <message>
        <source>&amp;Connect</source>
        <translation>&amp;Verbinden</translation>
    </message>
    <message>
        <source>Filter ROS topics or types…</source>
        <translation>ROS-Topics oder -Typen filtern …</translation>
    </message>
    <message>
        <source>Filter MQTT topics…</source>
        <translation>MQTT-Topics filtern …</translation>
    </message>
    <message>
        <source>in &amp;payloads too</source>
        <translation>auch in &amp;Nutzdaten</translation>
    </message>
    <message>
        <source>The password was not kept: %1</source>
        <translation>Das Passwort wurde nicht gespeichert: %1</translation>
    </message>
    <message>
        <source>broker %1</source>
        <translation>Broker %1</translation>
    </message>
    <message>
        <source>asking %1…</source>
        <translation>frage %1 …</translation>
    </message>
    <message>
        <source>Dis&amp;connect</source>
        <translation>&amp;Trennen</translation>
    </message>
    <message>
        <source>%1 topics</source>
        <translation>%1 Topics</translation>
    </message>
    <message>
        <source>%1 messages</source>
        <translation>%1 Nachrichten</translation>
    </message>
    <message>
        <source>%1 dropped</source>
        <translation>%1 verworfen</translation>
    </message>
    <message>
        <source>%1 malformed</source>
        <translation>%1 fehlerhaft</translation>
    </message>
    <message>
        <source>&amp;Publish…</source>
        <translation>&amp;Veröffentlichen…</translation>
    </message>
    <message>
        <source>Publish a message to the selected topic (Ctrl+P)</source>
        <translation>Eine Nachricht an das gewählte Topic veröffentlichen (Strg+P)</translation>
    </message>
    <message>
        <source>&amp;Clear Retained…</source>
        <translation>Retained-Nachricht &amp;löschen…</translation>
    </message>
    <message>
        <source>Delete the retained message of the selected topic, or of every topic under a level (Del)</source>
        <translation>Die Retained-Nachricht des gewählten Topics löschen, oder die aller Topics unter einer Ebene (Entf)</translation>
    </message>
    <message>
        <source>Clear Retained</source>
        <translation>Retained-Nachricht löschen</translation>
    </message>
    <message>
        <source>No retained message is known at or under %1.</source>
        <translation>Unter %1 ist keine Retained-Nachricht bekannt.</translation>
    </message>
    <message>
        <source>Clear the retained message of %1? The broker deletes it; new subscribers get nothing until the next retained message.</source>
        <translation>Die Retained-Nachricht von %1 löschen? Der Broker entfernt sie; neue Abonnenten erhalten nichts bis zur nächsten Retained-Nachricht.</translation>
    </message>
    <message numerus="yes">
        <source>Clear the retained messages of %n topics at or under %1? The broker deletes them all.</source>
        <translation>
            <numerusform>Die Retained-Nachricht von %n Topic unter %1 löschen? Der Broker entfernt sie.</numerusform>
            <numerusform>Die Retained-Nachrichten von %n Topics unter %1 löschen? Der Broker entfernt sie alle.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1 of %n retained messages were not cleared: %2</source>
        <translation>
            <numerusform>%1 von %n Retained-Nachricht wurde nicht gelöscht: %2</numerusform>
            <numerusform>%1 von %n Retained-Nachrichten wurden nicht gelöscht: %2</numerusform>
        </translation>
    </message>
    <message>
        <source>ROS 1</source>
        <translation>ROS 1</translation>
    </message>
    <message>
        <source>ROS 2</source>
        <translation>ROS 2</translation>
    </message>
    <message>
        <source>ROS 1 and ROS 2</source>
        <translation>ROS 1 und ROS 2</translation>
    </message>
    <message>
        <source>The ROS graphs to show: ROS 1 through its master, ROS 2 through DDS discovery (no ROS 2 install needed), or both as two tabs</source>
        <translation>Die anzuzeigenden ROS-Graphen: ROS 1 über seinen Master, ROS 2 über die DDS-Erkennung (ohne ROS-2-Installation) oder beide in zwei Reitern</translation>
    </message>
    <message>
        <source>ROS &amp;graph:</source>
        <translation>ROS-&amp;Graph:</translation>
    </message>
    <message>
        <source>domain </source>
        <translation>Domäne </translation>
    </message>
    <message>
        <source>ROS 2 domain id (ROS_DOMAIN_ID); Enter joins it</source>
        <translation>ROS-2-Domänen-ID (ROS_DOMAIN_ID); Enter tritt ihr bei</translation>
    </message>
    <message>
        <source>this &amp;host only</source>
        <translation>nur dieser &amp;Rechner</translation>
    </message>
    <message>
        <source>Discover ROS 2 participants on 127.0.0.1 only, as ROS_LOCALHOST_ONLY=1 does</source>
        <translation>ROS-2-Teilnehmer nur auf 127.0.0.1 suchen, wie ROS_LOCALHOST_ONLY=1</translation>
    </message>
    <message>
        <source>Filter ROS 2 topics or types…</source>
        <translation>ROS-2-Topics oder -Typen filtern…</translation>
    </message>
    <message>
        <source>ROS &amp;1</source>
        <translation>ROS &amp;1</translation>
    </message>
    <message>
        <source>ROS &amp;2</source>
        <translation>ROS &amp;2</translation>
    </message>
    <message>
        <source>not shown (ROS 2 only)</source>
        <translation>nicht angezeigt (nur ROS 2)</translation>
    </message>
    <message numerus="yes">
        <source>%n topic(s) of an unknown ROS 2 type</source>
        <translation>
            <numerusform>%n Topic eines unbekannten ROS-2-Typs</numerusform>
            <numerusform>%n Topics unbekannter ROS-2-Typen</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 payloads evicted from the history (budget %2 MiB)</source>
        <translation>%1 Nutzdaten aus dem Verlauf verdrängt (Budget %2 MiB)</translation>
    </message>
    <message>
        <source>%1 messages on topics not tracked (budget %2 topics, %3 MiB of names)</source>
        <translation>%1 Nachrichten auf nicht erfassten Topics (Budget %2 Topics, %3 MiB Namen)</translation>
    </message>
</context>
<context>
    <name>DiscoveryLints</name>
    <message>
        <source>If its publishers send text or numbers, set primitive: true (a std_msgs type is chosen from the payload)</source>
        <translation>Senden seine Publisher Text oder Zahlen, primitive: true setzen (ein std_msgs-Typ wird nach den Nutzdaten gewählt)</translation>
    </message>
    <message>
        <source>or set ros_type to the std_msgs type of the payload (e.g. std_msgs/msg/Float64) together with primitive: true</source>
        <translation>oder ros_type auf den std_msgs-Typ der Nutzdaten setzen (z. B. std_msgs/msg/Float64), zusammen mit primitive: true</translation>
    </message>
    <message>
        <source>if they send JSON, set json: true and ros_type to the message its fields fill</source>
        <translation>senden sie JSON, json: true setzen und ros_type auf die Nachricht, die seine Felder füllen</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; carries messages but no mqtt_client announced their type on &apos;mqtt_client/ros_msg_type/%2&apos;, so the bridge waits for one and never publishes them on ROS (mqtt_client issues #12, #78).</source>
        <translation>%1: Auf &apos;%2&apos; kommen Nachrichten, aber kein mqtt_client hat ihren Typ auf &apos;mqtt_client/ros_msg_type/%2&apos; angekündigt; die Bridge wartet darauf und veröffentlicht sie nie auf ROS (mqtt_client-Issues #12, #78).</translation>
    </message>
    <message>
        <source>Set ros_type to the type the bridge must carry; publishers of other types are then left out.</source>
        <translation>ros_type auf den Typ setzen, den die Bridge übertragen soll; Publisher anderer Typen bleiben dann außen vor.</translation>
    </message>
    <message>
        <source>Give the topics of different types different names: ros_type, which fixes the type, needs mqtt_client 2.3.</source>
        <translation>Den Topics verschiedener Typen verschiedene Namen geben: ros_type, das den Typ festlegt, braucht mqtt_client 2.3.</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is published with %3 types (%4); without ros_type the bridge takes the type of the publisher it finds first, and a publisher of another type stops or breaks the link (mqtt_client issues #15, #45).</source>
        <translation>%1: &apos;%2&apos; wird mit %3 Typen veröffentlicht (%4); ohne ros_type nimmt die Bridge den Typ des Publishers, den sie zuerst findet, und ein Publisher eines anderen Typs hält die Verbindung an oder bricht sie (mqtt_client-Issues #15, #45).</translation>
    </message>
    <message>
        <source>%1: ros_type is &apos;%2&apos;, but &apos;%3&apos; is published as %4 only: the bridge&apos;s subscription matches no publisher.</source>
        <translation>%1: ros_type ist &apos;%2&apos;, aber &apos;%3&apos; wird nur als %4 veröffentlicht: das Abonnement der Bridge passt zu keinem Publisher.</translation>
    </message>
    <message>
        <source>Set ros_type to %1, or remove it to take the publishers&apos; type.</source>
        <translation>ros_type auf %1 setzen oder entfernen, um den Typ der Publisher zu nehmen.</translation>
    </message>
    <message>
        <source>Set advanced.ros.qos.reliability and .durability to auto (the default from mqtt_client 2.3), or to what the publishers offer.</source>
        <translation>advanced.ros.qos.reliability und .durability auf auto setzen (die Vorgabe ab mqtt_client 2.3) oder auf das, was die Publisher anbieten.</translation>
    </message>
    <message>
        <source>Offer at least what the subscribers ask for in advanced.ros.qos.reliability and .durability.</source>
        <translation>In advanced.ros.qos.reliability und .durability mindestens bieten, was die Subscriber verlangen.</translation>
    </message>
    <message>
        <source>mqtt_client 2.2 has no advanced.ros.qos: make the publishers offer reliable, volatile, or target 2.3 or later.</source>
        <translation>mqtt_client 2.2 kennt advanced.ros.qos nicht: die Publisher reliable, volatile anbieten lassen oder 2.3 oder neuer als Ziel wählen.</translation>
    </message>
    <message>
        <source>%1: mqtt_client&apos;s subscription to &apos;%2&apos; cannot match a publisher: %3 (mqtt_client issue #48).</source>
        <translation>%1: Das Abonnement von mqtt_client auf &apos;%2&apos; passt zu keinem Publisher: %3 (mqtt_client-Issue #48).</translation>
    </message>
    <message>
        <source>%1: subscribers of &apos;%2&apos; cannot get mqtt_client&apos;s messages: %3 (mqtt_client issue #48).</source>
        <translation>%1: Subscriber von &apos;%2&apos; können die Nachrichten von mqtt_client nicht erhalten: %3 (mqtt_client-Issue #48).</translation>
    </message>
    <message>
        <source>Nodes that are discovery clients announce themselves to the server only: Bridgescope joins the domain by simple discovery and does not see them either.</source>
        <translation>Knoten, die Discovery-Clients sind, melden sich nur beim Server: Bridgescope tritt der Domäne per Simple Discovery bei und sieht sie ebenfalls nicht.</translation>
    </message>
    <message>
        <source>This lab uses a Fast DDS discovery server (ROS_DISCOVERY_SERVER=%1). A bridge started there as a plain client is told only of the endpoints it matches, and then bridges nothing of the ROS topics it has to find by name (mqtt_client issue #67).%2</source>
        <translation>Dieses Labor nutzt einen Fast-DDS-Discovery-Server (ROS_DISCOVERY_SERVER=%1). Eine dort als einfacher Client gestartete Bridge erfährt nur von den Endpunkten, zu denen sie passt, und überträgt dann nichts von den ROS-Topics, die sie über den Namen finden muss (mqtt_client-Issue #67).%2</translation>
    </message>
    <message>
        <source>Start mqtt_client as a super client: export ROS_SUPER_CLIENT=TRUE, or give it a FASTRTPS_DEFAULT_PROFILES_FILE whose participant&apos;s discovery protocol is SUPER_CLIENT.</source>
        <translation>mqtt_client als Super-Client starten: export ROS_SUPER_CLIENT=TRUE, oder eine FASTRTPS_DEFAULT_PROFILES_FILE mitgeben, deren Participant das Discovery-Protokoll SUPER_CLIENT hat.</translation>
    </message>
</context>
<context>
    <name>EcdfChart</name>
    <message>
        <source>latency [ms]</source>
        <translation>Latenz [ms]</translation>
    </message>
    <message>
        <source>ECDF</source>
        <translation>ECDF</translation>
    </message>
    <message>
        <source>Check a series in the table to plot its ECDF</source>
        <translation>Eine Reihe in der Tabelle ankreuzen, um ihre ECDF zu zeichnen</translation>
    </message>
    <message>
        <source>Latency ECDF</source>
        <translation>Latenz-ECDF</translation>
    </message>
    <message>
        <source>Made with Bridgescope</source>
        <translation>Erstellt mit Bridgescope</translation>
    </message>
    <message>
        <source>cannot encode the chart as PNG</source>
        <translation>das Diagramm lässt sich nicht als PNG kodieren</translation>
    </message>
    <message>
        <source>%1: a chart is saved as SVG or PNG; give the file the suffix .svg or .png</source>
        <translation>%1: ein Diagramm wird als SVG oder PNG gespeichert; die Datei braucht die Endung .svg oder .png</translation>
    </message>
    <message numerus="yes">
        <source>%n beyond %1 ms</source>
        <translation>
            <numerusform>%n jenseits von %1 ms</numerusform>
            <numerusform>%n jenseits von %1 ms</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>EcdfSvg</name>
    <message>
        <source>latency [ms]</source>
        <translation>Latenz [ms]</translation>
    </message>
    <message>
        <source>dashed: mean · dotted: median</source>
        <translation>gestrichelt: Mittel · gepunktet: Median</translation>
    </message>
    <message numerus="yes">
        <source>%1: %n beyond %2 ms</source>
        <translation>
            <numerusform>%1: %n jenseits von %2 ms</numerusform>
            <numerusform>%1: %n jenseits von %2 ms</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>EventLogModel</name>
    <message>
        <source>%1 ended</source>
        <translation>%1 beendet</translation>
    </message>
    <message>
        <source>bridge %1</source>
        <translation>Bridge %1</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <source>Level</source>
        <translation>Stufe</translation>
    </message>
    <message>
        <source>Link</source>
        <translation>Verbindung</translation>
    </message>
    <message>
        <source>What</source>
        <translation>Was</translation>
    </message>
    <message>
        <source>Duration</source>
        <translation>Dauer</translation>
    </message>
</context>
<context>
    <name>ExperimentCommand</name>
    <message>
        <source>The experiment&apos;s folder: its plan, state and a run per cell.</source>
        <translation>Der Ordner des Experiments: sein Plan, sein Zustand und ein Messlauf je Zelle.</translation>
    </message>
    <message>
        <source>Go on with DIR: skip the complete cells, redo the one that was cut off and those that failed.</source>
        <translation>Mit DIR fortfahren: vollständige Zellen überspringen, die abgebrochene und die fehlgeschlagenen wiederholen.</translation>
    </message>
    <message>
        <source>List the cells and the time they will take; run nothing.</source>
        <translation>Die Zellen und ihre voraussichtliche Dauer auflisten; nichts ausführen.</translation>
    </message>
    <message>
        <source>The experiment plan (docs/formats.md).</source>
        <translation>Der Experimentplan (docs/formats.md).</translation>
    </message>
    <message>
        <source>experiment takes one plan; see bridgescope experiment --help</source>
        <translation>experiment nimmt einen Plan; siehe bridgescope experiment --help</translation>
    </message>
    <message>
        <source>experiment needs -o DIR, the folder its runs go to</source>
        <translation>experiment braucht -o DIR, den Ordner für seine Messläufe</translation>
    </message>
    <message numerus="yes">
        <source>%1: %n cell(s), %2 samples each after %3 of warm-up</source>
        <translation>
            <numerusform>%1: %n Zelle, je %2 Proben nach %3 zum Einschwingen</numerusform>
            <numerusform>%1: %n Zellen, je %2 Proben nach %3 zum Einschwingen</numerusform>
        </translation>
    </message>
    <message>
        <source>about %1 in all</source>
        <translation>insgesamt etwa %1</translation>
    </message>
    <message>
        <source>cell %1/%2: %3</source>
        <translation>Zelle %1/%2: %3</translation>
    </message>
    <message>
        <source>cell %1/%2 failed: %3</source>
        <translation>Zelle %1/%2 fehlgeschlagen: %3</translation>
    </message>
    <message>
        <source>cell %1/%2: %3/%4 samples, about %5 left</source>
        <translation>Zelle %1/%2: %3/%4 Proben, noch etwa %5</translation>
    </message>
    <message>
        <source>stopped; bridgescope experiment --resume goes on</source>
        <translation>angehalten; bridgescope experiment --resume macht weiter</translation>
    </message>
    <message>
        <source>%1 of %2 cells complete in %3</source>
        <translation>%1 von %2 Zellen vollständig in %3</translation>
    </message>
    <message>
        <source>throughput: %1 bytes at %2 Hz</source>
        <translation>Durchsatz: %1 Bytes mit %2 Hz</translation>
    </message>
    <message>
        <source>Runs an experiment plan unattended: every cell of its matrix (payload, rate, QoS, TLS, announcement, queue size, bridge implementation, link profile) on its own lab, recorded as a run in DIR. Progress on standard error; on standard output one JSON line per cell started and finished, and a progress line a second with the totals (ms) of the samples since the last; Ctrl+C stops after cleaning up, and --resume goes on. bridgescope report DIR makes the tables.
Exit status: 0 every cell complete, 1 a cell failed, 2 bad options or plan, 130 stopped.</source>
        <translation>Führt einen Experimentplan unbeaufsichtigt aus: jede Zelle seiner Matrix (Nutzlast, Rate, QoS, TLS, Ankündigung, Warteschlangenlänge, Bridge-Implementierung, Streckenprofil) in einem eigenen Labor, aufgezeichnet als Messlauf in DIR. Fortschritt auf der Standardfehlerausgabe; auf der Standardausgabe eine JSON-Zeile je begonnener und beendeter Zelle und jede Sekunde eine Fortschrittszeile mit den Gesamtlatenzen (ms) der Proben seit der letzten; Strg+C hält nach dem Aufräumen an, --resume macht weiter. bridgescope report DIR erstellt die Tabellen.
Rückgabewert: 0 alle Zellen vollständig, 1 eine Zelle fehlgeschlagen, 2 falsche Optionen oder falscher Plan, 130 angehalten.</translation>
    </message>
    <message>
        <source>--broker and --ros-master go together, unless the plan&apos;s servers give the other</source>
        <translation>--broker und --ros-master gehören zusammen, außer die Server des Plans geben das andere an</translation>
    </message>
    <message>
        <source>Run every cell on this broker instead of the plan&apos;s servers; it may carry a user and password, which no file, log or command line of a child gets.</source>
        <translation>Jede Zelle auf diesem Broker statt auf den Servern des Plans ausführen; er darf Benutzer und Passwort enthalten, die keine Datei, kein Log und keine Befehlszeile eines Kindprozesses erhält.</translation>
    </message>
    <message>
        <source>The ROS master that goes with --broker (default: the plan&apos;s).</source>
        <translation>Der ROS-Master zu --broker (Vorgabe: der des Plans).</translation>
    </message>
    <message>
        <source>    fails: %1</source>
        <translation>    scheitert: %1</translation>
    </message>
    <message>
        <source>--ros-master: the plan runs on ROS 2 (ros: 2), which has no master</source>
        <translation>--ros-master: der Plan läuft auf ROS 2 (ros: 2), das keinen Master hat</translation>
    </message>
</context>
<context>
    <name>ExperimentFindings</name>
    <message>
        <source>%1 ms [%2, %3] ms, 95 %</source>
        <translation>%1 ms [%2, %3] ms, 95 %</translation>
    </message>
    <message>
        <source>%1: no significant difference between %2 and %3: the totals shift by %4 (the means: %5 and %6 ms)</source>
        <translation>%1: kein signifikanter Unterschied zwischen %2 und %3: die Gesamtwerte verschieben sich um %4 (die Mittelwerte: %5 und %6 ms)</translation>
    </message>
    <message>
        <source>%1: the total mean is lowest at %2 (%3 ms) and highest at %4 (%5 ms), %6 ms more (%7 %)</source>
        <translation>%1: der mittlere Gesamtwert ist bei %2 am niedrigsten (%3 ms) und bei %4 am höchsten (%5 ms), %6 ms mehr (%7 %)</translation>
    </message>
    <message>
        <source>; the totals shift by %1</source>
        <translation>; die Gesamtwerte verschieben sich um %1</translation>
    </message>
    <message>
        <source> (too few samples for an interval)</source>
        <translation> (zu wenige Samples für ein Intervall)</translation>
    </message>
    <message>
        <source>Cell %1 (%2) failed: %3</source>
        <translation>Zelle %1 (%2) fehlgeschlagen: %3</translation>
    </message>
    <message>
        <source>Cell %1 (%2) is not done (%3): --resume finishes it.</source>
        <translation>Zelle %1 (%2) ist nicht fertig (%3): --resume vollendet sie.</translation>
    </message>
    <message>
        <source>Cell %1 is left out: %2</source>
        <translation>Zelle %1 bleibt unberücksichtigt: %2</translation>
    </message>
    <message>
        <source>Throughput with %1 (%2 bytes): up to %3 Hz sustained, %4 MB/s.</source>
        <translation>Durchsatz mit %1 (%2 Bytes): bis %3 Hz gehalten, %4 MB/s.</translation>
    </message>
    <message>
        <source>Throughput with %1 (%2 bytes): not even %3 Hz was sustained.</source>
        <translation>Durchsatz mit %1 (%2 Bytes): nicht einmal %3 Hz wurden gehalten.</translation>
    </message>
    <message>
        <source>; most of it in %1 (%2 ms).</source>
        <translation>; das meiste davon in %1 (%2 ms).</translation>
    </message>
    <message>
        <source>QoS 1 and 2 wait for the broker&apos;s acknowledgements (PUBACK; PUBREC, PUBREL, PUBCOMP), and a client without TCP_NODELAY (Paho) can wait for a delayed ACK of up to 40 ms on each.</source>
        <translation>QoS 1 und 2 warten auf die Bestätigungen des Brokers (PUBACK; PUBREC, PUBREL, PUBCOMP), und ein Client ohne TCP_NODELAY (Paho) kann auf jede bis zu 40 ms auf ein verzögertes ACK warten.</translation>
    </message>
    <message>
        <source>Announcing the type before every message (mqtt_client 2.2.1) puts a small publish in front of each message; without TCP_NODELAY the message then waits for the delayed ACK of the first, up to 40 ms.</source>
        <translation>Die Typankündigung vor jeder Nachricht (mqtt_client 2.2.1) stellt jeder Nachricht eine kleine Veröffentlichung voran; ohne TCP_NODELAY wartet die Nachricht dann bis zu 40 ms auf das verzögerte ACK der ersten.</translation>
    </message>
    <message>
        <source>The smallest payload (%1) is slower through the interfaces than %2 (%3 against %4 ms): small messages wait for delayed ACKs where Nagle&apos;s algorithm holds them.</source>
        <translation>Die kleinste Nutzlast (%1) ist in den Schnittstellen langsamer als %2 (%3 gegenüber %4 ms): kleine Nachrichten warten auf verzögerte ACKs, wo Nagles Algorithmus sie zurückhält.</translation>
    </message>
</context>
<context>
    <name>ExperimentPage</name>
    <message>
        <source>&amp;Run</source>
        <translation>&amp;Ausführen</translation>
    </message>
    <message>
        <source>Res&amp;ume</source>
        <translation>&amp;Fortsetzen</translation>
    </message>
    <message>
        <source>S&amp;top</source>
        <translation>An&amp;halten</translation>
    </message>
    <message>
        <source>&amp;Export Report…</source>
        <translation>Bericht &amp;exportieren …</translation>
    </message>
    <message>
        <source>Open a plan or an example, choose a folder, and run it.</source>
        <translation>Einen Plan oder ein Beispiel öffnen, einen Ordner wählen und ausführen.</translation>
    </message>
    <message>
        <source>&amp;Folder:</source>
        <translation>&amp;Ordner:</translation>
    </message>
    <message>
        <source>where the runs go (a new folder, or one to resume)</source>
        <translation>wohin die Messläufe gehen (ein neuer Ordner oder einer zum Fortsetzen)</translation>
    </message>
    <message>
        <source>&amp;Browse…</source>
        <translation>&amp;Durchsuchen …</translation>
    </message>
    <message>
        <source>Run every cell of the plan into a new folder (Ctrl+R)</source>
        <translation>Jede Zelle des Plans in einen neuen Ordner ausführen (Strg+R)</translation>
    </message>
    <message>
        <source>Go on with the folder: skip the complete cells, redo the others</source>
        <translation>Mit dem Ordner fortfahren: vollständige Zellen überspringen, die anderen wiederholen</translation>
    </message>
    <message>
        <source>Stop after cleaning up; Resume goes on</source>
        <translation>Nach dem Aufräumen anhalten; Fortsetzen macht weiter</translation>
    </message>
    <message>
        <source>Experiment</source>
        <translation>Experiment</translation>
    </message>
    <message>
        <source>&amp;Open Plan…</source>
        <translation>Plan ö&amp;ffnen …</translation>
    </message>
    <message>
        <source>Save Plan &amp;As…</source>
        <translation>Plan speichern &amp;unter …</translation>
    </message>
    <message>
        <source>Open F&amp;older…</source>
        <translation>O&amp;rdner öffnen …</translation>
    </message>
    <message>
        <source>An experiment&apos;s folder: its plan, cells and report</source>
        <translation>Der Ordner eines Experiments: sein Plan, seine Zellen und sein Bericht</translation>
    </message>
    <message>
        <source>Open Experiment</source>
        <translation>Experiment öffnen</translation>
    </message>
    <message>
        <source>Examples…</source>
        <translation>Beispiele …</translation>
    </message>
    <message>
        <source>The plans that reproduce the shapes of the paper&apos;s Tables I-V</source>
        <translation>Die Pläne, die die Form der Tabellen I-V der Veröffentlichung nachbilden</translation>
    </message>
    <message>
        <source>name: QoS study
samples: 600
factors:
  qos: [0, 1, 2]</source>
        <translation>name: QoS-Studie
samples: 600
factors:
  qos: [0, 1, 2]</translation>
    </message>
    <message>
        <source>Experiment plan</source>
        <translation>Experimentplan</translation>
    </message>
    <message>
        <source>Cells</source>
        <translation>Zellen</translation>
    </message>
    <message>
        <source>Double-click or Enter: open a finished cell&apos;s run on the Measure page</source>
        <translation>Doppelklick oder Eingabe: den Messlauf einer fertigen Zelle auf der Seite Messen öffnen</translation>
    </message>
    <message>
        <source>Experiment log</source>
        <translation>Experimentprotokoll</translation>
    </message>
    <message>
        <source>S&amp;tatistic:</source>
        <translation>&amp;Kennzahl:</translation>
    </message>
    <message>
        <source>Re&amp;fresh</source>
        <translation>Aktualisie&amp;ren</translation>
    </message>
    <message>
        <source>Totals (ECDF)</source>
        <translation>Gesamtlatenzen (ECDF)</translation>
    </message>
    <message>
        <source>Report</source>
        <translation>Bericht</translation>
    </message>
    <message>
        <source>%1 is not an experiment&apos;s folder (it has no %2)</source>
        <translation>%1 ist kein Experimentordner (es fehlt %2)</translation>
    </message>
    <message>
        <source>Not a plan: %1</source>
        <translation>Kein Plan: %1</translation>
    </message>
    <message>
        <source>experiment</source>
        <translation>Experiment</translation>
    </message>
    <message numerus="yes">
        <source>%1: %n cell(s) of %2 samples, about %3</source>
        <translation>
            <numerusform>%1: %n Zelle mit %2 Proben, etwa %3</numerusform>
            <numerusform>%1: %n Zellen mit je %2 Proben, etwa %3</numerusform>
        </translation>
    </message>
    <message>
        <source>No report yet: the folder holds no experiment.</source>
        <translation>Noch kein Bericht: der Ordner enthält kein Experiment.</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Zustand</translation>
    </message>
    <message>
        <source>Samples</source>
        <translation>Proben</translation>
    </message>
    <message>
        <source>Total median</source>
        <translation>Gesamt (Median)</translation>
    </message>
    <message>
        <source>Total p99</source>
        <translation>Gesamt (p99)</translation>
    </message>
    <message>
        <source>Cell</source>
        <translation>Zelle</translation>
    </message>
    <message>
        <source>Double-click to open %1 on the Measure page</source>
        <translation>Doppelklick öffnet %1 auf der Seite Messen</translation>
    </message>
    <message>
        <source>%1 of %2 cells complete, %3 failed.</source>
        <translation>%1 von %2 Zellen vollständig, %3 fehlgeschlagen.</translation>
    </message>
    <message>
        <source>An experiment is running already.</source>
        <translation>Es läuft bereits ein Experiment.</translation>
    </message>
    <message>
        <source>Choose the folder the experiment&apos;s runs go to.</source>
        <translation>Den Ordner für die Messläufe des Experiments wählen.</translation>
    </message>
    <message>
        <source>%1 holds an experiment already: Resume goes on with it, or choose another folder.</source>
        <translation>%1 enthält bereits ein Experiment: Fortsetzen macht damit weiter, oder einen anderen Ordner wählen.</translation>
    </message>
    <message>
        <source>Cannot make the folder %1.</source>
        <translation>Der Ordner %1 lässt sich nicht anlegen.</translation>
    </message>
    <message>
        <source>The experiment did not start: %1</source>
        <translation>Das Experiment ist nicht gestartet: %1</translation>
    </message>
    <message>
        <source>Starting…</source>
        <translation>Starte …</translation>
    </message>
    <message>
        <source>Stopping after cleaning up…</source>
        <translation>Halte nach dem Aufräumen an …</translation>
    </message>
    <message>
        <source>throughput: %1 Hz, %2 of %3 samples%4</source>
        <translation>Durchsatz: %1 Hz, %2 von %3 Proben%4</translation>
    </message>
    <message>
        <source>, not sustained</source>
        <translation>, nicht gehalten</translation>
    </message>
    <message>
        <source>Cell %1 of %2: %3, warming up; about %4 left</source>
        <translation>Zelle %1 von %2: %3, Einschwingen; noch etwa %4</translation>
    </message>
    <message>
        <source>Cell %1 of %2: %3, %4 of %5 samples; about %6 left</source>
        <translation>Zelle %1 von %2: %3, %4 von %5 Proben; noch etwa %6</translation>
    </message>
    <message>
        <source>The experiment crashed; Resume goes on with it.</source>
        <translation>Das Experiment ist abgestürzt; Fortsetzen macht damit weiter.</translation>
    </message>
    <message>
        <source>Every cell complete.</source>
        <translation>Alle Zellen vollständig.</translation>
    </message>
    <message>
        <source>Stopped; Resume goes on.</source>
        <translation>Angehalten; Fortsetzen macht weiter.</translation>
    </message>
    <message>
        <source>Done, but a cell failed: see its tooltip and the log.</source>
        <translation>Fertig, aber eine Zelle ist fehlgeschlagen: siehe ihren Tooltip und das Protokoll.</translation>
    </message>
    <message>
        <source>exit status %1</source>
        <translation>Rückgabewert %1</translation>
    </message>
    <message>
        <source>No report yet.</source>
        <translation>Noch kein Bericht.</translation>
    </message>
    <message>
        <source>There is no report yet.</source>
        <translation>Es gibt noch keinen Bericht.</translation>
    </message>
    <message>
        <source>Unknown report format &apos;%1&apos; (md, html, tex, csv, json, pdf).</source>
        <translation>Unbekanntes Berichtsformat &apos;%1&apos; (md, html, tex, csv, json, pdf).</translation>
    </message>
    <message>
        <source>Export Report</source>
        <translation>Bericht exportieren</translation>
    </message>
    <message>
        <source>PDF (*.pdf);;Markdown (*.md);;HTML (*.html);;LaTeX (*.tex);;CSV (*.csv);;JSON (*.json)</source>
        <translation>PDF (*.pdf);;Markdown (*.md);;HTML (*.html);;LaTeX (*.tex);;CSV (*.csv);;JSON (*.json)</translation>
    </message>
    <message>
        <source>Report written to %1</source>
        <translation>Bericht nach %1 geschrieben</translation>
    </message>
    <message>
        <source>Cell %1 is %2: only a complete cell has a run to open.</source>
        <translation>Zelle %1 ist %2: nur eine vollständige Zelle hat einen Messlauf zum Öffnen.</translation>
    </message>
    <message>
        <source>Experiment Folder</source>
        <translation>Experimentordner</translation>
    </message>
    <message>
        <source>Open Plan</source>
        <translation>Plan öffnen</translation>
    </message>
    <message>
        <source>Experiment plans (*.yaml *.yml);;All files (*)</source>
        <translation>Experimentpläne (*.yaml *.yml);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Save Plan</source>
        <translation>Plan speichern</translation>
    </message>
    <message>
        <source>Experiment plans (*.yaml *.yml)</source>
        <translation>Experimentpläne (*.yaml *.yml)</translation>
    </message>
    <message>
        <source>%1 (#%2)</source>
        <translation>%1 (#%2)</translation>
    </message>
    <message numerus="yes">
        <source>%n line(s) of the experiment&apos;s output were no event and were left out.</source>
        <translation>
            <numerusform>%n Zeile der Ausgabe des Experiments war kein Ereignis und wurde ausgelassen.</numerusform>
            <numerusform>%n Zeilen der Ausgabe des Experiments waren keine Ereignisse und wurden ausgelassen.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>ExperimentPlan</name>
    <message>
        <source>no link profile &apos;%1&apos; under links:</source>
        <translation>kein Verbindungsprofil &apos;%1&apos; unter links:</translation>
    </message>
    <message>
        <source>no bridge &apos;%1&apos; under bridges: (or reference)</source>
        <translation>keine Bridge &apos;%1&apos; unter bridges: (oder reference)</translation>
    </message>
    <message>
        <source>a level of %1 is a single value</source>
        <translation>eine Stufe von %1 ist ein einzelner Wert</translation>
    </message>
    <message>
        <source>payload is bytes (20000), a percentage of the 0.18 MB scan (25%), scan or pointcloud2; not &apos;%1&apos;</source>
        <translation>payload ist eine Bytezahl (20000), ein Prozentsatz des 0,18-MB-Scans (25%), scan oder pointcloud2; nicht &apos;%1&apos;</translation>
    </message>
    <message>
        <source>detection_ms takes 0 to 10000 ms</source>
        <translation>detection_ms nimmt 0 bis 10000 ms</translation>
    </message>
    <message>
        <source>qos is 0, 1 or 2</source>
        <translation>qos ist 0, 1 oder 2</translation>
    </message>
    <message>
        <source>tls is true or false</source>
        <translation>tls ist true oder false</translation>
    </message>
    <message>
        <source>announce is once or every_message</source>
        <translation>announce ist once oder every_message</translation>
    </message>
    <message>
        <source>queue_size takes 1 to 100000</source>
        <translation>queue_size nimmt 1 bis 100000</translation>
    </message>
    <message>
        <source>unknown factor &apos;%1&apos; (known: %2)</source>
        <translation>unbekannter Faktor &apos;%1&apos; (bekannt: %2)</translation>
    </message>
    <message>
        <source>repetition %1</source>
        <translation>Wiederholung %1</translation>
    </message>
    <message>
        <source>baseline</source>
        <translation>Grundeinstellung</translation>
    </message>
    <message>
        <source>a plan is a mapping: name, samples, factors or cells, …</source>
        <translation>ein Plan ist eine Zuordnung: name, samples, factors oder cells, …</translation>
    </message>
    <message>
        <source>two cells are the same: %1</source>
        <translation>zwei Zellen sind gleich: %1</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>%1 min</source>
        <translation>%1 min</translation>
    </message>
    <message>
        <source>%1 h %2 min</source>
        <translation>%1 h %2 min</translation>
    </message>
    <message>
        <source>rate_hz takes %1 to 1000 Hz</source>
        <translation>rate_hz erwartet %1 bis 1000 Hz</translation>
    </message>
    <message>
        <source>announce %1 cannot be honoured: the bridge %2 announces %3 (its entry under bridges: says so)</source>
        <translation>announce %1 ist nicht einzuhalten: die Bridge %2 kündigt %3 an (so sagt es ihr Eintrag unter bridges:)</translation>
    </message>
    <message>
        <source>announce once cannot be honoured: what the bridge %1&apos;s command announces is not known (the real mqtt_client announces every message); say announce: every_message (or once) in its entry under bridges:</source>
        <translation>announce once ist nicht einzuhalten: was der Befehl der Bridge %1 ankündigt, ist nicht bekannt (der echte mqtt_client kündigt jede Nachricht an); announce: every_message (oder once) in ihrem Eintrag unter bridges: angeben</translation>
    </message>
    <message>
        <source>%1 takes a number from 0 to %2</source>
        <translation>%1 nimmt eine Zahl von 0 bis %2</translation>
    </message>
    <message>
        <source>a bridge is reference or {command: &quot;… {config} … {name} …&quot;, announce: once | every_message}</source>
        <translation>eine Bridge ist reference oder {command: &quot;… {config} … {name} …&quot;, announce: once | every_message}</translation>
    </message>
    <message>
        <source>a bridge&apos;s announce is once or every_message (what its command does)</source>
        <translation>announce einer Bridge ist once oder every_message (was ihr Befehl tut)</translation>
    </message>
    <message>
        <source>the bridge command must use {config}, the generated config&apos;s path</source>
        <translation>der Bridge-Befehl muss {config} verwenden, den Pfad der erzeugten Konfiguration</translation>
    </message>
    <message>
        <source>%1 takes a whole number from %2 to %3</source>
        <translation>%1 nimmt eine ganze Zahl von %2 bis %3</translation>
    </message>
    <message>
        <source>timeout_s takes 1 to %1 seconds</source>
        <translation>timeout_s erwartet 1 bis %1 Sekunden</translation>
    </message>
    <message>
        <source>ros is 1 (a ROS master) or 2 (DDS, a private domain per cell)</source>
        <translation>ros ist 1 (ein ROS-Master) oder 2 (DDS, eine eigene Domain je Zelle)</translation>
    </message>
    <message>
        <source>servers given are {broker: URL, ros_master: URI}</source>
        <translation>angegebene Server sind {broker: URL, ros_master: URI}</translation>
    </message>
    <message>
        <source>a plan holds no credentials (it is copied next to its runs): give the broker without user and password</source>
        <translation>ein Plan enthält keine Zugangsdaten (er wird neben seinen Messläufen abgelegt): den Broker ohne Benutzer und Passwort angeben</translation>
    </message>
    <message>
        <source>servers is embedded or {broker: URL, ros_master: URI}</source>
        <translation>servers ist embedded oder {broker: URL, ros_master: URI}</translation>
    </message>
    <message>
        <source>pipeline is paper or a pipeline file</source>
        <translation>pipeline ist paper oder eine Pipeline-Datei</translation>
    </message>
    <message>
        <source>bridges names implementations: {NAME: {command: …}}</source>
        <translation>bridges benennt Implementierungen: {NAME: {command: …}}</translation>
    </message>
    <message>
        <source>links names profiles: {NAME: {delay_ms: …}}</source>
        <translation>links benennt Profile: {NAME: {delay_ms: …}}</translation>
    </message>
    <message>
        <source>throughput is {rates_hz: [10, 20, …], seconds: N}</source>
        <translation>throughput ist {rates_hz: [10, 20, …], seconds: N}</translation>
    </message>
    <message>
        <source>a rate from %1 to 10000 Hz</source>
        <translation>eine Rate von %1 bis 10000 Hz</translation>
    </message>
    <message>
        <source>seconds per rate from 1 to 3600</source>
        <translation>Sekunden je Rate von 1 bis 3600</translation>
    </message>
    <message>
        <source>defaults is a mapping of factor: level</source>
        <translation>defaults ist eine Zuordnung Faktor: Stufe</translation>
    </message>
    <message>
        <source>give factors (crossed) or cells (listed), not both</source>
        <translation>factors (gekreuzt) oder cells (aufgezählt) angeben, nicht beides</translation>
    </message>
    <message>
        <source>factors is a mapping of factor: [levels]</source>
        <translation>factors ist eine Zuordnung Faktor: [Stufen]</translation>
    </message>
    <message>
        <source>factor &apos;%1&apos; twice</source>
        <translation>Faktor &apos;%1&apos; doppelt</translation>
    </message>
    <message>
        <source>%1 needs a list of levels</source>
        <translation>%1 braucht eine Liste von Stufen</translation>
    </message>
    <message>
        <source>more than %1 cells</source>
        <translation>mehr als %1 Zellen</translation>
    </message>
    <message>
        <source>cells is a list of {factor: level, …}</source>
        <translation>cells ist eine Liste von {Faktor: Stufe, …}</translation>
    </message>
    <message>
        <source>a cell is {factor: level, …}</source>
        <translation>eine Zelle ist {Faktor: Stufe, …}</translation>
    </message>
    <message>
        <source>a link profile is {delay_ms, jitter_ms, bandwidth_mbit, loss_percent, there_extra_ms}</source>
        <translation>ein Verbindungsprofil ist {delay_ms, jitter_ms, bandwidth_mbit, loss_percent, there_extra_ms}</translation>
    </message>
    <message>
        <source>unknown link setting &apos;%1&apos; (known: delay_ms, jitter_ms, bandwidth_mbit, loss_percent, there_extra_ms)</source>
        <translation>unbekannte Verbindungseinstellung „%1“ (bekannt: delay_ms, jitter_ms, bandwidth_mbit, loss_percent, there_extra_ms)</translation>
    </message>
</context>
<context>
    <name>ExperimentReport</name>
    <message>
        <source>its pipeline differs from the first cell&apos;s</source>
        <translation>seine Pipeline weicht von der der ersten Zelle ab</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a statistic (mean, median, std, p99)</source>
        <translation>&apos;%1&apos; ist keine Kennzahl (mean, median, std, p99)</translation>
    </message>
    <message>
        <source>mean</source>
        <translation>Mittel</translation>
    </message>
    <message>
        <source>median</source>
        <translation>Median</translation>
    </message>
    <message>
        <source>std</source>
        <translation>Std.-Abw.</translation>
    </message>
    <message>
        <source>p99</source>
        <translation>p99</translation>
    </message>
    <message>
        <source>Experiment report: %1</source>
        <translation>Experimentbericht: %1</translation>
    </message>
    <message>
        <source>%1 cells: %2 complete, %3 failed; %4 samples a cell after %5 of warm-up. Latencies in ms; a group&apos;s value is the sum of its stages in each sample, a level pools the samples of its cells.</source>
        <translation>%1 Zellen: %2 vollständig, %3 fehlgeschlagen; %4 Proben je Zelle nach %5 zum Einschwingen. Latenzen in ms; der Wert einer Gruppe ist die Summe ihrer Stufen in jeder Probe, eine Stufe fasst die Proben ihrer Zellen zusammen.</translation>
    </message>
    <message>
        <source>stage group</source>
        <translation>Stufengruppe</translation>
    </message>
    <message>
        <source>no complete cell</source>
        <translation>keine vollständige Zelle</translation>
    </message>
    <message>
        <source>Cells: %1.</source>
        <translation>Zellen: %1.</translation>
    </message>
    <message>
        <source>Cells</source>
        <translation>Zellen</translation>
    </message>
    <message>
        <source>cell</source>
        <translation>Zelle</translation>
    </message>
    <message>
        <source>levels</source>
        <translation>Stufen</translation>
    </message>
    <message>
        <source>state</source>
        <translation>Zustand</translation>
    </message>
    <message>
        <source>samples</source>
        <translation>Proben</translation>
    </message>
    <message>
        <source>total mean</source>
        <translation>Gesamt (Mittel)</translation>
    </message>
    <message>
        <source>run</source>
        <translation>Lauf</translation>
    </message>
    <message>
        <source>Findings</source>
        <translation>Befunde</translation>
    </message>
    <message>
        <source>Throughput</source>
        <translation>Durchsatz</translation>
    </message>
    <message>
        <source>The highest publishing rate sustained (every sample through in its window, none dropped, the total&apos;s median within twice the lowest rate&apos;s plus 5 ms), and the payload it carries.</source>
        <translation>Die höchste gehaltene Veröffentlichungsrate (jede Probe in ihrem Fenster durch, keine verworfen, der Median der Gesamtlatenz höchstens doppelt so hoch wie bei der niedrigsten Rate plus 5 ms) und die Nutzlast, die sie trägt.</translation>
    </message>
    <message>
        <source>payload</source>
        <translation>Nutzlast</translation>
    </message>
    <message>
        <source>bytes</source>
        <translation>Bytes</translation>
    </message>
    <message>
        <source>highest rate (Hz)</source>
        <translation>höchste Rate (Hz)</translation>
    </message>
    <message>
        <source>rates tried (samples/expected, median total ms)</source>
        <translation>versuchte Raten (Proben/erwartet, Median gesamt ms)</translation>
    </message>
    <message>
        <source>total</source>
        <translation>gesamt</translation>
    </message>
    <message>
        <source>Total latency by %1</source>
        <translation>Gesamtlatenz nach %1</translation>
    </message>
    <message>
        <source>Per stage (Table I layout, mean, ms)</source>
        <translation>Je Stufe (Aufbau von Tabelle I, Mittel, ms)</translation>
    </message>
    <message>
        <source>stage</source>
        <translation>Stufe</translation>
    </message>
    <message>
        <source>Mean latencies [ms] by method</source>
        <translation>Mittlere Latenzen [ms] nach Verfahren</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>ROS 2 (DDS, a private domain)</source>
        <translation>ROS 2 (DDS, eine eigene Domain)</translation>
    </message>
    <message>
        <source>ROS 1</source>
        <translation>ROS 1</translation>
    </message>
    <message>
        <source>ROS</source>
        <translation>ROS</translation>
    </message>
</context>
<context>
    <name>ExperimentRunner</name>
    <message>
        <source>openssl %1 failed: %2</source>
        <translation>openssl %1 fehlgeschlagen: %2</translation>
    </message>
    <message>
        <source>cannot write %1</source>
        <translation>%1 lässt sich nicht schreiben</translation>
    </message>
    <message>
        <source>cannot make %1</source>
        <translation>%1 lässt sich nicht anlegen</translation>
    </message>
    <message>
        <source>%1 holds an experiment already: --resume goes on with it, or give another folder</source>
        <translation>%1 enthält schon ein Experiment: --resume macht damit weiter, oder einen anderen Ordner angeben</translation>
    </message>
    <message>
        <source>%1 was made by another plan (its %2 differs): resume it with that plan, or give another folder</source>
        <translation>%1 stammt von einem anderen Plan (seine %2 weicht ab): mit jenem Plan fortsetzen oder einen anderen Ordner angeben</translation>
    </message>
    <message>
        <source>cut off; done again</source>
        <translation>abgebrochen; wird wiederholt</translation>
    </message>
    <message>
        <source>%1 of %2 samples after %3 s</source>
        <translation>%1 von %2 Proben nach %3 s</translation>
    </message>
    <message>
        <source>Experiment %1, cell %2: %3</source>
        <translation>Experiment %1, Zelle %2: %3</translation>
    </message>
    <message>
        <source>stopped; --resume does it again</source>
        <translation>angehalten; --resume wiederholt sie</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>not an experiment&apos;s state (%1)</source>
        <translation>kein Zustand eines Experiments (%1)</translation>
    </message>
    <message>
        <source>a symbolic link</source>
        <translation>ein symbolischer Link</translation>
    </message>
    <message>
        <source>missing</source>
        <translation>fehlt</translation>
    </message>
    <message>
        <source>not a regular file</source>
        <translation>keine reguläre Datei</translation>
    </message>
    <message>
        <source>the run of another cell, %1</source>
        <translation>der Lauf einer anderen Zelle, %1</translation>
    </message>
    <message>
        <source>%1 complete samples, the cell needs %2</source>
        <translation>%1 vollständige Samples, die Zelle braucht %2</translation>
    </message>
    <message>
        <source>its run %1 was not kept (%2); done again</source>
        <translation>ihr Lauf %1 wurde nicht behalten (%2); wird neu gemacht</translation>
    </message>
    <message>
        <source>cell %1: %2</source>
        <translation>Zelle %1: %2</translation>
    </message>
    <message>
        <source>not an experiment&apos;s state (larger than %1 MiB)</source>
        <translation>kein Zustand eines Experiments (größer als %1 MiB)</translation>
    </message>
    <message>
        <source>the broker %1 cannot be reached (%2)</source>
        <translation>der Broker %1 ist nicht erreichbar (%2)</translation>
    </message>
    <message>
        <source>the ROS master %1 cannot be reached (%2)</source>
        <translation>der ROS-Master %1 ist nicht erreichbar (%2)</translation>
    </message>
    <message>
        <source>no stamp has arrived</source>
        <translation>kein Zeitstempel ist angekommen</translation>
    </message>
    <message>
        <source>after %1 s: %2; still trying</source>
        <translation>nach %1 s: %2; versucht es weiter</translation>
    </message>
    <message>
        <source>%1 more</source>
        <translation>%1 weitere</translation>
    </message>
    <message>
        <source>no stamp ever arrived on %1 of %2 topics: %3</source>
        <translation>auf %1 von %2 Topics kam nie ein Zeitstempel an: %3</translation>
    </message>
    <message>
        <source>no stamp ever arrived on %1 of %2 topics under %3: %4</source>
        <translation>auf %1 von %2 Topics unter %3 kam nie ein Zeitstempel an: %4</translation>
    </message>
    <message>
        <source>; these are interface stamps, which the real mqtt_client does not publish (only the benchmarking suite&apos;s fork and the reference bridge do): give the plan a pipeline without the mqtt_interface_* topics</source>
        <translation>; das sind Schnittstellen-Zeitstempel, die der echte mqtt_client nicht veröffentlicht (nur der Fork der Benchmarking-Suite und die Referenz-Bridge tun es): dem Plan eine Pipeline ohne die mqtt_interface_*-Topics geben</translation>
    </message>
</context>
<context>
    <name>FieldPath</name>
    <message>
        <source>no field %1</source>
        <translation>kein Feld %1</translation>
    </message>
    <message>
        <source>%1 is no number</source>
        <translation>%1 ist keine Zahl</translation>
    </message>
</context>
<context>
    <name>FieldPlotChart</name>
    <message>
        <source>seconds</source>
        <translation>Sekunden</translation>
    </message>
    <message>
        <source>Wheel or + and - zoom the time, drag or Left and Right move it; double-click or Home follows the newest values again.</source>
        <translation>Mausrad oder + und - zoomen die Zeit, Ziehen oder Links und Rechts verschieben sie; Doppelklick oder Pos1 folgt wieder den neuesten Werten.</translation>
    </message>
    <message>
        <source>Zoomed or moved: double-click or press Home to follow the newest values</source>
        <translation>Gezoomt oder verschoben: Doppelklick oder Pos1 folgt wieder den neuesten Werten</translation>
    </message>
</context>
<context>
    <name>FieldPlotter</name>
    <message>
        <source>the announced type %1 does not read</source>
        <translation>der angekündigte Typ %1 ist nicht lesbar</translation>
    </message>
    <message>
        <source>the type is not known yet</source>
        <translation>der Typ ist noch nicht bekannt</translation>
    </message>
    <message>
        <source>a payload of %1 bytes, more than %2 are not plotted</source>
        <translation>Nutzdaten von %1 Bytes; mehr als %2 werden nicht geplottet</translation>
    </message>
    <message>
        <source>not JSON: %1</source>
        <translation>kein JSON: %1</translation>
    </message>
    <message>
        <source>no ROS 2 definition of %1 is known</source>
        <translation>für %1 ist keine ROS-2-Definition bekannt</translation>
    </message>
</context>
<context>
    <name>FleetModel</name>
    <message>
        <source>Host</source>
        <translation>Rechner</translation>
    </message>
    <message>
        <source>Bridge</source>
        <translation>Bridge</translation>
    </message>
    <message>
        <source>Link</source>
        <translation>Verbindung</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Zustand</translation>
    </message>
    <message>
        <source>Source Hz</source>
        <translation>Quelle Hz</translation>
    </message>
    <message>
        <source>Destination Hz</source>
        <translation>Ziel Hz</translation>
    </message>
    <message>
        <source>Loss %</source>
        <translation>Verlust %</translation>
    </message>
    <message>
        <source>p99 ms</source>
        <translation>p99 ms</translation>
    </message>
    <message>
        <source>Why</source>
        <translation>Warum</translation>
    </message>
    <message>
        <source>Messages per second, the mean of the last %1 s (the window of the rate chart)</source>
        <translation>Nachrichten pro Sekunde, Mittel der letzten %1 s (das Fenster des Ratendiagramms)</translation>
    </message>
</context>
<context>
    <name>FleetSnapshotBuilder</name>
    <message>
        <source>host stopped reporting</source>
        <translation>Rechner meldet nicht mehr</translation>
    </message>
    <message>
        <source>host stopped reporting since %1</source>
        <translation>Rechner meldet seit %1 nicht mehr</translation>
    </message>
    <message>
        <source>unknown (the watch on %1 cannot see both sides)</source>
        <translation>unbekannt (die Überwachung auf %1 sieht nicht beide Seiten)</translation>
    </message>
    <message>
        <source>the bridge %1 on %2 is down</source>
        <translation>die Bridge %1 auf %2 ist ausgefallen</translation>
    </message>
</context>
<context>
    <name>FleetSource</name>
    <message>
        <source>cannot read the fleet from %1: %2</source>
        <translation>die Flotte lässt sich nicht von %1 lesen: %2</translation>
    </message>
</context>
<context>
    <name>FleetView</name>
    <message>
        <source>http://prometheus:9090</source>
        <translation>http://prometheus:9090</translation>
    </message>
    <message>
        <source>no basic auth</source>
        <translation>ohne Basic Auth</translation>
    </message>
    <message>
        <source>Kept in the system keyring, never in a file</source>
        <translation>Im Schlüsselbund des Systems aufbewahrt, nie in einer Datei</translation>
    </message>
    <message>
        <source>C&amp;onnect</source>
        <translation>&amp;Verbinden</translation>
    </message>
    <message>
        <source>Prometheus &amp;URL:</source>
        <translation>Prometheus-&amp;URL:</translation>
    </message>
    <message>
        <source>U&amp;ser:</source>
        <translation>Be&amp;nutzer:</translation>
    </message>
    <message>
        <source>Pass&amp;word:</source>
        <translation>Pass&amp;wort:</translation>
    </message>
    <message>
        <source>Choose the Prometheus server that scrapes the watches of the fleet.</source>
        <translation>Den Prometheus-Server wählen, der die Überwachungen der Flotte abfragt.</translation>
    </message>
    <message>
        <source>Destination rate, last %1 minutes</source>
        <translation>Rate am Ziel, letzte %1 Minuten</translation>
    </message>
    <message>
        <source>Latency p99, last %1 minutes</source>
        <translation>Latenz p99, letzte %1 Minuten</translation>
    </message>
    <message>
        <source>Reading the fleet from %1…</source>
        <translation>Lese die Flotte von %1 …</translation>
    </message>
    <message>
        <source>%1 (the links as of %2)</source>
        <translation>%1 (die Verbindungen mit Stand %2)</translation>
    </message>
    <message>
        <source>Links: %1 on %2 hosts, %3 not reporting, as of %4</source>
        <translation>Verbindungen: %1 auf %2 Rechnern, %3 melden nicht, Stand %4</translation>
    </message>
    <message>
        <source>; %1 series past the bound, %2 of the wrong form left out</source>
        <translation>; %1 Reihen über der Grenze, %2 in falscher Form ausgelassen</translation>
    </message>
    <message>
        <source>Hz</source>
        <translation>Hz</translation>
    </message>
    <message>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <source>The password was not kept: %1.</source>
        <translation>Das Passwort wurde nicht aufbewahrt: %1.</translation>
    </message>
</context>
<context>
    <name>GraphStatus</name>
    <message>
        <source>asking the master…</source>
        <translation>frage den Master …</translation>
    </message>
    <message>
        <source>reachable: %1 topics, %2 nodes</source>
        <translation>erreichbar: %1 Topics, %2 Knoten</translation>
    </message>
    <message>
        <source>unreachable: %1 (retrying every second)</source>
        <translation>nicht erreichbar: %1 (neuer Versuch jede Sekunde)</translation>
    </message>
    <message>
        <source>listening on domain %1: no participant yet</source>
        <translation>lausche auf Domäne %1: noch kein Teilnehmer</translation>
    </message>
    <message>
        <source>domain %1: participants %2, topics %3, nodes %4</source>
        <translation>Domäne %1: Teilnehmer %2, Topics %3, Knoten %4</translation>
    </message>
    <message>
        <source>unreadable node announcements %1</source>
        <translation>unlesbare Knotenmeldungen %1</translation>
    </message>
    <message>
        <source>no node</source>
        <translation>kein Knoten</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keins</translation>
    </message>
    <message>
        <source>%1; publishers: %2; subscribers: %3</source>
        <translation>%1; Publisher: %2; Subscriber: %3</translation>
    </message>
</context>
<context>
    <name>Gui</name>
    <message>
        <source>Render the main window to PNG and exit.</source>
        <translation>Das Hauptfenster als PNG speichern und beenden.</translation>
    </message>
    <message>
        <source>Seconds to wait before the screenshot.</source>
        <translation>Sekunden Wartezeit vor dem Bildschirmfoto.</translation>
    </message>
    <message>
        <source>--after takes a number of seconds</source>
        <translation>--after erwartet eine Anzahl Sekunden</translation>
    </message>
    <message>
        <source>Cannot write the screenshot %1</source>
        <translation>Bildschirmfoto %1 lässt sich nicht schreiben</translation>
    </message>
    <message>
        <source>MQTT broker to connect to (tcp://host:port, ssl://...).</source>
        <translation>MQTT-Broker, mit dem verbunden wird (tcp://host:port, ssl://...).</translation>
    </message>
    <message>
        <source>ROS master URI (default $ROS_MASTER_URI).</source>
        <translation>ROS-Master-URI (Vorgabe $ROS_MASTER_URI).</translation>
    </message>
    <message>
        <source>MQTT broker (tcp://host:1883, ssl://host:8883, mqtt://, mqtts://)</source>
        <translation>MQTT-Broker (tcp://host:1883, ssl://host:8883, mqtt://, mqtts://)</translation>
    </message>
    <message>
        <source>ROS master (default $ROS_MASTER_URI)</source>
        <translation>ROS-Master (Vorgabe $ROS_MASTER_URI)</translation>
    </message>
    <message>
        <source>render the main window to PNG and exit</source>
        <translation>das Hauptfenster als PNG speichern und beenden</translation>
    </message>
    <message>
        <source>wait this long before the screenshot (default 1)</source>
        <translation>so lange vor dem Bildschirmfoto warten (Vorgabe 1)</translation>
    </message>
    <message>
        <source>show this help</source>
        <translation>diese Hilfe anzeigen</translation>
    </message>
    <message>
        <source>show the version</source>
        <translation>die Version anzeigen</translation>
    </message>
    <message>
        <source>check, convert and pair bridge configs</source>
        <translation>Bridge-Konfigurationen prüfen, umwandeln und paaren</translation>
    </message>
    <message>
        <source>       bridgescope &lt;command&gt; [options]</source>
        <translation>        bridgescope &lt;Befehl&gt; [Optionen]</translation>
    </message>
    <message>
        <source>Discover ROS and MQTT topics, bridge them with mqtt_client, and measure the link.</source>
        <translation>ROS- und MQTT-Topics entdecken, mit mqtt_client verbinden und die Strecke vermessen.</translation>
    </message>
    <message>
        <source>Options:</source>
        <translation>Optionen:</translation>
    </message>
    <message>
        <source>Commands:</source>
        <translation>Befehle:</translation>
    </message>
    <message>
        <source>Run &apos;bridgescope &lt;command&gt; --help&apos; for the options of a command.</source>
        <translation>&apos;bridgescope &lt;Befehl&gt; --help&apos; zeigt die Optionen eines Befehls.</translation>
    </message>
    <message>
        <source>measure with this pipeline</source>
        <translation>mit dieser Pipeline messen</translation>
    </message>
    <message>
        <source>Measure with this pipeline (the suite&apos;s metrics-logger YAML).</source>
        <translation>Mit dieser Pipeline messen (die Metrics-Logger-YAML der Suite).</translation>
    </message>
    <message>
        <source>--page takes one of: %1</source>
        <translation>--page erwartet eins von: %1</translation>
    </message>
    <message>
        <source>record a measurement run</source>
        <translation>einen Messlauf aufzeichnen</translation>
    </message>
    <message>
        <source>latency reports of runs, CSV files and bags</source>
        <translation>Latenzberichte zu Läufen, CSV-Dateien und Bags</translation>
    </message>
    <message>
        <source>start the embedded demo lab and show it</source>
        <translation>das eingebaute Demo-Labor starten und anzeigen</translation>
    </message>
    <message>
        <source>run a config as a reference bridge</source>
        <translation>eine Konfiguration als Referenz-Bridge ausführen</translation>
    </message>
    <message>
        <source>round trips and throughput through the broker</source>
        <translation>Umlaufzeiten und Durchsatz über den Broker</translation>
    </message>
    <message>
        <source>the demo lab without a window</source>
        <translation>das Demo-Labor ohne Fenster</translation>
    </message>
    <message>
        <source>Start the embedded demo lab and show it.</source>
        <translation>Das eingebaute Demo-Labor starten und anzeigen.</translation>
    </message>
    <message>
        <source>starting the demo lab…</source>
        <translation>starte das Demo-Labor …</translation>
    </message>
    <message>
        <source>the demo lab did not start: %1</source>
        <translation>das Demo-Labor ist nicht gestartet: %1</translation>
    </message>
    <message>
        <source>Bridgescope — demo lab</source>
        <translation>Bridgescope — Demo-Labor</translation>
    </message>
    <message>
        <source>The demo lab stopped: %1</source>
        <translation>Das Demo-Labor hat sich beendet: %1</translation>
    </message>
    <message>
        <source>debug messages of every layer on stderr, also after a command</source>
        <translation>Debug-Meldungen jeder Schicht auf stderr, auch hinter einem Befehl</translation>
    </message>
    <message>
        <source>watch every bridged link for hours: events, metrics</source>
        <translation>jede gebridgte Verbindung stundenlang überwachen: Ereignisse, Metriken</translation>
    </message>
    <message>
        <source>run an experiment matrix unattended, a run per cell</source>
        <translation>eine Experimentmatrix unbeaufsichtigt ausführen, ein Messlauf je Zelle</translation>
    </message>
    <message>
        <source>open on a page: discover, map, measure, reports, links or experiments</source>
        <translation>auf einer Seite öffnen: discover, map, measure, reports, links oder experiments</translation>
    </message>
    <message>
        <source>Open on this page: discover, map, measure, reports, links or experiments.</source>
        <translation>Auf dieser Seite öffnen: discover, map, measure, reports, links oder experiments.</translation>
    </message>
    <message>
        <source>Usage: bridgescope [--broker URL] [--ros-master URI] [options] [FILE | EXPERIMENT-DIR]...</source>
        <translation>Aufruf: bridgescope [--broker URL] [--ros-master URI] [Optionen] [DATEI | EXPERIMENT-ORDNER]...</translation>
    </message>
    <message>
        <source>Files open where they belong: a bridge config on the Map page (more configs on Links), a pipeline or one run, suite CSV or bag on Measure, several of those on Reports, an experiment&apos;s folder on Experiments.</source>
        <translation>Dateien öffnen dort, wo sie hingehören: eine Bridge-Konfiguration auf der Seite Zuordnen (weitere Konfigurationen unter Verbindungen), eine Pipeline oder ein Lauf, eine Suite-CSV oder ein Bag unter Messen, mehrere davon unter Berichte, der Ordner eines Experiments unter Experimente.</translation>
    </message>
    <message>
        <source>Bridge configs, pipelines, runs, suite CSVs, bags or experiment folders to open.</source>
        <translation>Zu öffnende Bridge-Konfigurationen, Pipelines, Läufe, Suite-CSVs, Bags oder Experiment-Ordner.</translation>
    </message>
    <message>
        <source>Starting the demo lab: mosquitto and rosmaster…</source>
        <translation>Das Demo-Labor startet: mosquitto und rosmaster …</translation>
    </message>
    <message>
        <source>Bridgescope — demo lab (starting)</source>
        <translation>Bridgescope — Demo-Labor (startet)</translation>
    </message>
    <message>
        <source>The demo lab did not start: %1</source>
        <translation>Das Demo-Labor ist nicht gestartet: %1</translation>
    </message>
    <message>
        <source>the servers did not listen within 20 s</source>
        <translation>die Server haben innerhalb von 20 s nicht angenommen</translation>
    </message>
    <message>
        <source>Starting the demo lab: bridges and nodes…</source>
        <translation>Das Demo-Labor startet: Bridges und Knoten …</translation>
    </message>
    <message>
        <source>Demo lab</source>
        <translation>Demo-Labor</translation>
    </message>
    <message>
        <source>colours: system (default), light or dark</source>
        <translation>Farben: system (Standard), light oder dark</translation>
    </message>
    <message>
        <source>Colours: system (default), light or dark.</source>
        <translation>Farben: system (Standard), light oder dark.</translation>
    </message>
    <message>
        <source>--theme takes one of: %1</source>
        <translation>--theme nimmt eines von: %1</translation>
    </message>
    <message>
        <source>ROS graphs to show: ROS 1 (master), ROS 2 (DDS) or both</source>
        <translation>anzuzeigende ROS-Graphen: ROS 1 (Master), ROS 2 (DDS) oder beide</translation>
    </message>
    <message>
        <source>ROS 2 domain (default $ROS_DOMAIN_ID, else 0)</source>
        <translation>ROS-2-Domäne (Standard $ROS_DOMAIN_ID, sonst 0)</translation>
    </message>
    <message>
        <source>ROS 2 discovery on this host only</source>
        <translation>ROS-2-Erkennung nur auf diesem Rechner</translation>
    </message>
    <message>
        <source>list ROS, ROS 2 and MQTT topics</source>
        <translation>ROS-, ROS-2- und MQTT-Topics auflisten</translation>
    </message>
    <message>
        <source>demo lab: broker %1, ROS master %2</source>
        <translation>Demo-Labor: Broker %1, ROS-Master %2</translation>
    </message>
    <message>
        <source>Point bridgescope discover, watch or mosquitto_sub at these; configs in %1</source>
        <translation>Richten Sie bridgescope discover, watch oder mosquitto_sub darauf; Konfigurationen in %1</translation>
    </message>
    <message>
        <source>Starting the demo lab: mosquitto…</source>
        <translation>Das Demo-Labor startet: mosquitto…</translation>
    </message>
    <message>
        <source>demo lab (ROS 2, domain %1): broker %2</source>
        <translation>Demo-Labor (ROS 2, Domain %1): Broker %2</translation>
    </message>
    <message>
        <source>ROS 2 (%1), the demo lab&apos;s domain</source>
        <translation>ROS 2 (%1), die Domain des Demo-Labors</translation>
    </message>
    <message>
        <source>with --screenshot: start from the saved window and save it, as a user&apos;s start does</source>
        <translation>mit --screenshot: vom gespeicherten Fenster ausgehen und es speichern, wie ein Start durch den Benutzer</translation>
    </message>
    <message>
        <source>With --screenshot: start from the saved window and save it on exit.</source>
        <translation>Mit --screenshot: vom gespeicherten Fenster ausgehen und es beim Beenden speichern.</translation>
    </message>
    <message>
        <source>answer clock probes; measure a far host&apos;s clock and its uncertainty</source>
        <translation>Uhrproben beantworten; die Uhr eines fernen Rechners und ihre Unsicherheit messen</translation>
    </message>
    <message>
        <source>print the Prometheus rules and alerts for watch --metrics</source>
        <translation>die Prometheus-Regeln und -Alarme für watch --metrics ausgeben</translation>
    </message>
    <message>
        <source>the Links page shows every host&apos;s links from this Prometheus server</source>
        <translation>die Seite Verbindungen zeigt die Verbindungen aller Rechner von diesem Prometheus-Server</translation>
    </message>
    <message>
        <source>Show every host&apos;s links from this Prometheus server on the Links page.</source>
        <translation>Die Verbindungen aller Rechner von diesem Prometheus-Server auf der Seite Verbindungen zeigen.</translation>
    </message>
</context>
<context>
    <name>LatencyStatsModel</name>
    <message>
        <source>Crosses from %1 to %2: the raw value includes the clock offset between the hosts.</source>
        <translation>Geht von %1 zu %2: der Rohwert enthält den Uhrenversatz zwischen den Rechnern.</translation>
    </message>
    <message>
        <source>Derived per sample: total minus every stage that stays on one host.</source>
        <translation>Je Probe abgeleitet: gesamt minus jede Stufe, die auf einem Rechner bleibt.</translation>
    </message>
    <message>
        <source>Half the round trip: the mean of both ways, as in the paper.</source>
        <translation>Halbe Umlaufzeit: das Mittel beider Richtungen, wie im Paper.</translation>
    </message>
    <message>
        <source>((c_in − v_out) − (v_in − c_out)) / 2 per sample, assuming both ways take as long.</source>
        <translation>((c_in − v_out) − (v_in − c_out)) / 2 je Probe, unter der Annahme, dass beide Richtungen gleich lang dauern.</translation>
    </message>
    <message>
        <source>Measured by the bridge itself (single-stage series).</source>
        <translation>Von der Bridge selbst gemessen (einstufige Reihe).</translation>
    </message>
    <message>
        <source>Stage</source>
        <translation>Stufe</translation>
    </message>
    <message>
        <source>Mean [ms]</source>
        <translation>Mittel [ms]</translation>
    </message>
    <message>
        <source>Median</source>
        <translation>Median</translation>
    </message>
    <message>
        <source>Std</source>
        <translation>Std.-Abw.</translation>
    </message>
    <message>
        <source>Min</source>
        <translation>Min.</translation>
    </message>
    <message>
        <source>Max</source>
        <translation>Max.</translation>
    </message>
    <message>
        <source>p90</source>
        <translation>p90</translation>
    </message>
    <message>
        <source>p95</source>
        <translation>p95</translation>
    </message>
    <message>
        <source>p99</source>
        <translation>p99</translation>
    </message>
    <message>
        <source>p99.9</source>
        <translation>p99,9</translation>
    </message>
    <message>
        <source>Count</source>
        <translation>Anzahl</translation>
    </message>
    <message>
        <source>± %1 ms</source>
        <translation>± %1 ms</translation>
    </message>
    <message>
        <source>The offset lies between %1 and %2 ms (neither leg takes negative time). </source>
        <translation>Der Versatz liegt zwischen %1 und %2 ms (keine Strecke dauert negativ). </translation>
    </message>
    <message>
        <source>Within that range, a difference between the two legs and a clock offset cannot be told apart: the estimate assumes both ways take as long. When both ends share one clock, say so (one_clock: true in the pipeline, or --one-clock) for each direction&apos;s own latency.</source>
        <translation>Innerhalb dieses Bereichs sind ein Unterschied der beiden Strecken und ein Uhrenversatz nicht zu unterscheiden: die Schätzung nimmt an, dass beide Wege gleich lange dauern. Teilen beide Enden eine Uhr, das angeben (one_clock: true in der Pipeline oder --one-clock), um die Latenz jeder Richtung zu erhalten.</translation>
    </message>
    <message>
        <source>Crosses from %1 to %2; both stamp with one clock: the value is its one-way latency.</source>
        <translation>Geht von %1 nach %2; beide stempeln mit einer Uhr: der Wert ist seine Einweg-Latenz.</translation>
    </message>
    <message>
        <source>One clock: this direction&apos;s own one-way latency, stamp to stamp.</source>
        <translation>Eine Uhr: die Einweg-Latenz dieser Richtung, Stempel zu Stempel.</translation>
    </message>
    <message>
        <source>Not a measurement: %1.</source>
        <translation>Keine Messung: %1.</translation>
    </message>
    <message>
        <source>%1 ms: smaller than its uncertainty (%2), so it cannot be told from zero.</source>
        <translation>%1 ms: kleiner als seine Unsicherheit (%2), also nicht von null zu unterscheiden.</translation>
    </message>
    <message>
        <source>Stamp to stamp, corrected by the offset between the clocks of %1 and %2 that the clock service measured: its one-way latency, within %3.</source>
        <translation>Zeitstempel zu Zeitstempel, korrigiert um den vom Uhrendienst gemessenen Versatz zwischen den Uhren von %1 und %2: seine Einweg-Latenz, auf %3 genau.</translation>
    </message>
    <message>
        <source>How much longer the way there takes than the way back, halved: what half the round trip (the paper&apos;s one way) misattributes to each way. Measured clocks; within %1.</source>
        <translation>Wie viel länger der Hinweg als der Rückweg dauert, halbiert: was die halbe Umlaufzeit (die eine Richtung des Papers) jeder Richtung falsch zuschreibt. Gemessene Uhren; auf %1 genau.</translation>
    </message>
    <message>
        <source>Crosses from %1 to %2: the raw value includes the clock offset between the hosts. Corrected by the measured clocks (pinned above): median %3 ms %4.</source>
        <translation>Geht von %1 zu %2: Der Rohwert enthält den Uhrenversatz zwischen den Rechnern. Mit den gemessenen Uhren korrigiert (oben angeheftet): Median %3 ms %4.</translation>
    </message>
    <message>
        <source>Observed hop latency, without stamps: each message Bridgescope saw going into the bridge matched by its content with the copy it saw coming out, on this computer&apos;s clock (its own delivery of both included). The Links page has the link&apos;s loss.</source>
        <translation>Beobachtete Sprunglatenz, ohne Zeitstempel: jede Nachricht, die Bridgescope in die Brücke gehen sah, nach ihrem Inhalt der Kopie zugeordnet, die es herauskommen sah, auf der Uhr dieses Rechners (seine eigene Zustellung beider eingeschlossen). Die Seite Verbindungen zeigt den Verlust der Verbindung.</translation>
    </message>
</context>
<context>
    <name>LatencyWarnings</name>
    <message>
        <source>median %1 ms: a latency cannot be negative, so the stamps&apos; order or their hosts are wrong</source>
        <translation>Median %1 ms: eine Latenz kann nicht negativ sein, also sind die Reihenfolge der Stempel oder ihre Hosts falsch</translation>
    </message>
    <message>
        <source>the order crosses between hosts %1 times where going there and back crosses %2 times: the stamps of one host are interleaved with another&apos;s</source>
        <translation>die Reihenfolge wechselt %1-mal zwischen Hosts, wo hin und zurück %2-mal wechselt: die Stempel eines Hosts sind mit denen eines anderen verschränkt</translation>
    </message>
    <message>
        <source>Set each stamp&apos;s host in the pipeline&apos;s Host column, or load a pipeline (Load Pipeline…).</source>
        <translation>Setzen Sie den Host jedes Stempels in der Spalte Host der Pipeline, oder laden Sie eine Pipeline (Pipeline laden…).</translation>
    </message>
    <message>
        <source>Set each stamp&apos;s host (hosts: in the pipeline file), or give the pipeline with --pipeline.</source>
        <translation>Setzen Sie den Host jedes Stempels (hosts: in der Pipeline-Datei), oder geben Sie die Pipeline mit --pipeline an.</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>LinkCells</name>
    <message>
        <source>ok</source>
        <translation>ok</translation>
    </message>
    <message>
        <source>warning</source>
        <translation>Warnung</translation>
    </message>
    <message>
        <source>alert</source>
        <translation>Alarm</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
</context>
<context>
    <name>LinkModel</name>
    <message>
        <source>%1 ended after %2 s</source>
        <translation>%1 endete nach %2 s</translation>
    </message>
    <message>
        <source>%1 since %2</source>
        <translation>%1 seit %2</translation>
    </message>
    <message>
        <source>A negative latency: the clocks of the bridge and of this computer differ.</source>
        <translation>Eine negative Latenz: die Uhren der Bridge und dieses Rechners gehen verschieden.</translation>
    </message>
    <message>
        <source>ROS → MQTT</source>
        <translation>ROS → MQTT</translation>
    </message>
    <message>
        <source>MQTT → ROS</source>
        <translation>MQTT → ROS</translation>
    </message>
    <message>
        <source>%1 % (%2)</source>
        <translation>%1 % (%2)</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Zustand</translation>
    </message>
    <message>
        <source>Bridge</source>
        <translation>Bridge</translation>
    </message>
    <message>
        <source>Direction</source>
        <translation>Richtung</translation>
    </message>
    <message>
        <source>Source</source>
        <translation>Quelle</translation>
    </message>
    <message>
        <source>Destination</source>
        <translation>Ziel</translation>
    </message>
    <message>
        <source>Lost</source>
        <translation>Verloren</translation>
    </message>
    <message>
        <source>p50 ms</source>
        <translation>p50 ms</translation>
    </message>
    <message>
        <source>p99 ms</source>
        <translation>p99 ms</translation>
    </message>
    <message>
        <source>Last event</source>
        <translation>Letztes Ereignis</translation>
    </message>
    <message>
        <source>No latency: the payloads carry no stamps, no mqtt_client latency topic and no pipeline timestamps cover this link.</source>
        <translation>Keine Latenz: Die Nutzdaten tragen keine Zeitstempel, und weder ein Latenz-Topic von mqtt_client noch Zeitstempel einer Pipeline decken diese Verbindung ab.</translation>
    </message>
    <message>
        <source>Latency from the stamps mqtt_client puts in front of the payloads.</source>
        <translation>Latenz aus den Zeitstempeln, die mqtt_client den Nutzdaten voranstellt.</translation>
    </message>
    <message>
        <source>Latency from mqtt_client&apos;s ~/latencies topic.</source>
        <translation>Latenz aus dem Topic ~/latencies von mqtt_client.</translation>
    </message>
    <message>
        <source>Latency from the pipeline&apos;s timestamp topics (PREFIX/in to PREFIX/out).</source>
        <translation>Latenz aus den Zeitstempel-Topics der Pipeline (PREFIX/in bis PREFIX/out).</translation>
    </message>
    <message>
        <source>Discovered: an mqtt_client announces this topic&apos;s type, no open config maps it. Only its MQTT end is watched (rate, bytes, stamps, Header.seq); open the bridge&apos;s config to watch both ends.</source>
        <translation>Entdeckt: Ein mqtt_client kündigt den Typ dieses Topics an, keine geöffnete Konfiguration bildet es ab. Nur das MQTT-Ende wird beobachtet (Rate, Bytes, Zeitstempel, Header.seq); öffnen Sie die Konfiguration der Bridge, um beide Enden zu beobachten.</translation>
    </message>
    <message>
        <source>(announced by a bridge)</source>
        <translation>(von einer Bridge angekündigt)</translation>
    </message>
    <message>
        <source>Observed hop latency: needs both ends; only the MQTT end of a discovered link is watched.</source>
        <translation>Beobachtete Latenz des Abschnitts: braucht beide Enden; von einem entdeckten Link wird nur das MQTT-Ende beobachtet.</translation>
    </message>
    <message>
        <source>Observed hop latency: each message seen going in matched by its content with the copy seen coming out, on this computer&apos;s clock, over the last 60 s (median). Matched %1, lost %2, identical contents not told apart %3, arrived with nothing seen going in %4.</source>
        <translation>Beobachtete Latenz des Abschnitts: jede hineingehende Nachricht über ihren Inhalt mit der herauskommenden Kopie verknüpft, nach der Uhr dieses Rechners, über die letzten 60 s (Median). Zugeordnet %1, verloren %2, gleiche Inhalte nicht unterscheidbar %3, angekommen ohne gesehenen Eingang %4.</translation>
    </message>
    <message>
        <source>%1 dropped unjudged: more waited than the matcher holds.</source>
        <translation>%1 unbeurteilt verworfen: es warteten mehr, als die Zuordnung hält.</translation>
    </message>
    <message>
        <source>Negative: this computer got the copies before the originals (its two subscriptions&apos; delivery, not the bridge).</source>
        <translation>Negativ: dieser Rechner bekam die Kopien vor den Originalen (die Zustellung seiner beiden Abonnements, nicht die Bridge).</translation>
    </message>
    <message>
        <source>Messages per second at the source, over the last 5 s</source>
        <translation>Nachrichten je Sekunde an der Quelle, über die letzten 5 s</translation>
    </message>
    <message>
        <source>Messages per second at the destination, over the last 5 s</source>
        <translation>Nachrichten je Sekunde am Ziel, über die letzten 5 s</translation>
    </message>
    <message>
        <source>Observed hop latency, median over the last 60 s: each message seen going into the bridge matched by its content with the copy seen coming out, on this computer&apos;s clock. No stamps needed.</source>
        <translation>Beobachtete Latenz des Abschnitts, Median über die letzten 60 s: jede in die Bridge gehende Nachricht über ihren Inhalt mit der herauskommenden Kopie verknüpft, nach der Uhr dieses Rechners. Ohne Zeitstempel.</translation>
    </message>
    <message>
        <source>The destination&apos;s rate over the last 5 minutes</source>
        <translation>Die Rate am Ziel über die letzten 5 Minuten</translation>
    </message>
    <message>
        <source>Src Hz</source>
        <translation>Qu. Hz</translation>
    </message>
    <message>
        <source>Dst Hz</source>
        <translation>Ziel Hz</translation>
    </message>
    <message>
        <source>Hop ms</source>
        <translation>Abschn. ms</translation>
    </message>
    <message>
        <source>5 min</source>
        <translation>5 min</translation>
    </message>
    <message>
        <source>Observed hop (no stamps): p50 %1 ms, p99 %2 ms over 60 s; %3 matched, %4 lost (%5 %), %6 not told apart, %7 with nothing seen going in</source>
        <translation>Beobachteter Sprung (ohne Zeitstempel): p50 %1 ms, p99 %2 ms über 60 s; %3 zugeordnet, %4 verloren (%5 %), %6 nicht unterscheidbar, %7 ohne gesehenen Eingang</translation>
    </message>
    <message>
        <source>%1 dropped unjudged</source>
        <translation>%1 unbewertet verworfen</translation>
    </message>
    <message>
        <source>Observed hop latency: a JSON link is matched by the message its payload makes, which needs the mapping&apos;s ros_type (mqtt_client 2.5 requires it too).</source>
        <translation>Beobachtete Hop-Latenz: Eine JSON-Verbindung wird über die Nachricht abgeglichen, die ihre Nutzlast ergibt; dafür braucht es den ros_type der Zuordnung (auch mqtt_client 2.5 verlangt ihn).</translation>
    </message>
    <message>
        <source>%1 JSON payloads not converted to %2</source>
        <translation>%1 JSON-Nutzlasten nicht in %2 umgewandelt</translation>
    </message>
    <message>
        <source>JSON: each MQTT payload is converted to %1 as mqtt_client 2.5 converts it, and matched with the ROS 2 message by the bytes that makes (%2 were not converted and are not matched: not the type&apos;s JSON, or past the watch&apos;s 4 MiB of JSON a drain; a message whose JSON the bridge shortened, such as a byte array of more than 100 elements, counts as lost).</source>
        <translation>JSON: Jede MQTT-Nutzlast wird wie von mqtt_client 2.5 in %1 umgewandelt und über die so entstehenden Bytes mit der ROS-2-Nachricht abgeglichen (%2 wurden nicht umgewandelt und werden nicht abgeglichen: kein JSON des Typs oder jenseits der 4 MiB JSON je Durchgang der Überwachung; eine Nachricht, deren JSON die Bridge gekürzt hat, etwa um ein Byte-Array mit mehr als 100 Elementen, zählt als verloren).</translation>
    </message>
</context>
<context>
    <name>LinkMonitor</name>
    <message>
        <source>the source %1 has been silent for %2 s</source>
        <translation>die Quelle %1 schweigt seit %2 s</translation>
    </message>
    <message>
        <source>nothing arrived on %1 for %2 s while %3 publishes</source>
        <translation>auf %1 kam %2 s lang nichts an, während %3 sendet</translation>
    </message>
    <message>
        <source>%1 % of the messages lost</source>
        <translation>%1 % der Nachrichten verloren</translation>
    </message>
    <message>
        <source>%1 Hz at the destination</source>
        <translation>%1 Hz am Ziel</translation>
    </message>
    <message>
        <source>%1 Hz at the destination for %2 Hz at the source</source>
        <translation>%1 Hz am Ziel bei %2 Hz an der Quelle</translation>
    </message>
    <message>
        <source>latency p99 %1 ms</source>
        <translation>Latenz p99 %1 ms</translation>
    </message>
    <message>
        <source>the bridge %1 left its last will</source>
        <translation>die Bridge %1 hat ihren letzten Willen hinterlassen</translation>
    </message>
    <message>
        <source>the bridge %1 carries nothing while its sources publish</source>
        <translation>die Bridge %1 überträgt nichts, während ihre Quellen senden</translation>
    </message>
    <message>
        <source>unknown (%1)</source>
        <translation>unbekannt (%1)</translation>
    </message>
    <message>
        <source>%1 carries messages again, not yet steadily for %2 s</source>
        <translation>%1 erhält wieder Nachrichten, noch nicht stetig %2 s lang</translation>
    </message>
    <message>
        <source>broker unreachable</source>
        <translation>Broker nicht erreichbar</translation>
    </message>
    <message>
        <source>ROS master unreachable</source>
        <translation>ROS-Master nicht erreichbar</translation>
    </message>
    <message>
        <source>ROS 2 domain unreachable</source>
        <translation>ROS-2-Domäne nicht erreichbar</translation>
    </message>
</context>
<context>
    <name>LinkProbe</name>
    <message>
        <source>the connection to the broker was lost</source>
        <translation>die Verbindung zum Broker ging verloren</translation>
    </message>
    <message>
        <source>the connection to the broker was lost: %1</source>
        <translation>die Verbindung zum Broker ging verloren: %1</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>angehalten</translation>
    </message>
    <message>
        <source>nothing came back at %1 Hz</source>
        <translation>bei %1 Hz kam nichts zurück</translation>
    </message>
    <message>
        <source>%1 % lost at %2 Hz</source>
        <translation>%1 % verloren bei %2 Hz</translation>
    </message>
    <message>
        <source>median round trip %1 ms at %2 Hz (limit %3 ms)</source>
        <translation>Median der Umlaufzeit %1 ms bei %2 Hz (Grenze %3 ms)</translation>
    </message>
    <message>
        <source>the sender reached only %1 of %2 Hz</source>
        <translation>der Sender erreichte nur %1 von %2 Hz</translation>
    </message>
    <message>
        <source>reached the maximum rate of %1 Hz</source>
        <translation>Höchstrate von %1 Hz erreicht</translation>
    </message>
    <message>
        <source>reached the time limit of %1 s</source>
        <translation>Zeitgrenze von %1 s erreicht</translation>
    </message>
    <message>
        <source>--size must be between %1 and %2 bytes</source>
        <translation>--size muss zwischen %1 und %2 Bytes liegen</translation>
    </message>
    <message>
        <source>--qos must be 0, 1 or 2</source>
        <translation>--qos muss 0, 1 oder 2 sein</translation>
    </message>
    <message>
        <source>--count must be between 1 and 100000000</source>
        <translation>--count muss zwischen 1 und 100000000 liegen</translation>
    </message>
    <message>
        <source>--max-rate must be at least --rate and at most 1000000 Hz</source>
        <translation>--max-rate muss mindestens --rate und höchstens 1000000 Hz sein</translation>
    </message>
    <message>
        <source>the sweep needs positive durations and a factor above 1</source>
        <translation>der Sweep braucht positive Dauern und einen Faktor über 1</translation>
    </message>
    <message>
        <source>--rate must be from %1 to 1000000 Hz</source>
        <translation>--rate muss zwischen %1 und 1000000 Hz liegen</translation>
    </message>
</context>
<context>
    <name>LinkRelay</name>
    <message>
        <source>the link relay cannot listen: %1</source>
        <translation>das Verbindungsrelais kann nicht lauschen: %1</translation>
    </message>
    <message>
        <source>the link relay cannot listen on &apos;%1&apos;: not an IP address</source>
        <translation>das Verbindungsrelais kann nicht auf „%1“ lauschen: keine IP-Adresse</translation>
    </message>
</context>
<context>
    <name>LinksPage</name>
    <message>
        <source>&amp;Add Configs…</source>
        <translation>Konfigurationen &amp;hinzufügen…</translation>
    </message>
    <message>
        <source>R&amp;ules…</source>
        <translation>Re&amp;geln…</translation>
    </message>
    <message>
        <source>Filter links…</source>
        <translation>Verbindungen filtern…</translation>
    </message>
    <message>
        <source>Select a link to see its history.</source>
        <translation>Eine Verbindung wählen, um ihren Verlauf zu sehen.</translation>
    </message>
    <message>
        <source>Destination rate:</source>
        <translation>Rate am Ziel:</translation>
    </message>
    <message>
        <source>Latency p99:</source>
        <translation>Latenz p99:</translation>
    </message>
    <message>
        <source>%1 is not a bridge config that can be read</source>
        <translation>%1 ist keine lesbare Bridge-Konfiguration</translation>
    </message>
    <message>
        <source>Watch Bridge Configs</source>
        <translation>Bridge-Konfigurationen überwachen</translation>
    </message>
    <message>
        <source>Bridge configs (*.yaml *.yml);;All files (*)</source>
        <translation>Bridge-Konfigurationen (*.yaml *.yml);;Alle Dateien (*)</translation>
    </message>
    <message numerus="yes">
        <source>%n link(s): %1 ok, %2 warning, %3 alert</source>
        <translation>
            <numerusform>%n Verbindung: %1 ok, %2 Warnung, %3 Alarm</numerusform>
            <numerusform>%n Verbindungen: %1 ok, %2 Warnung, %3 Alarm</numerusform>
        </translation>
    </message>
    <message>
        <source>Hz</source>
        <translation>Hz</translation>
    </message>
    <message>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <source>Bridgescope: %1</source>
        <translation>Bridgescope: %1</translation>
    </message>
    <message>
        <source>Edit the thresholds (a rules YAML) every link is held to</source>
        <translation>Die Schwellen (eine Regel-YAML) bearbeiten, an denen jede Verbindung gemessen wird</translation>
    </message>
    <message>
        <source>&amp;Discovered</source>
        <translation>&amp;Entdeckte</translation>
    </message>
    <message>
        <source>Also watch the links mqtt_client announces on the broker that no open config maps (their MQTT end)</source>
        <translation>Auch die Verbindungen beobachten, die mqtt_client am Broker ankündigt und keine geöffnete Konfiguration abbildet (ihr MQTT-Ende)</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt; → &lt;b&gt;%2&lt;/b&gt; (%3)</source>
        <translation>&lt;b&gt;%1&lt;/b&gt; → &lt;b&gt;%2&lt;/b&gt; (%3)</translation>
    </message>
    <message>
        <source>%1 messages at the source, %2 at the destination, %3 lost, %4 Header.seq gaps, %5 duplicates, %6 reordered, %7 stalls</source>
        <translation>%1 Nachrichten an der Quelle, %2 am Ziel, %3 verloren, %4 Header.seq-Lücken, %5 Duplikate, %6 umgeordnet, %7 Stillstände</translation>
    </message>
    <message>
        <source>List more bridge configs (one per vehicle or robot); check one to watch it</source>
        <translation>Weitere Bridge-Konfigurationen auflisten (eine je Fahrzeug oder Roboter); zum Beobachten abhaken</translation>
    </message>
    <message>
        <source>Watch config</source>
        <translation>Konfiguration beobachten</translation>
    </message>
    <message>
        <source>Links</source>
        <translation>Verbindungen</translation>
    </message>
    <message>
        <source>ROS</source>
        <translation>ROS</translation>
    </message>
    <message>
        <source>ROS 2</source>
        <translation>ROS 2</translation>
    </message>
    <message>
        <source>MQTT</source>
        <translation>MQTT</translation>
    </message>
    <message>
        <source>Check a config to watch its links (Space checks the current one). Opening or editing a config subscribes to nothing; watching subscribes to the topics counted here, at most %1 links in all.</source>
        <translation>Eine Konfiguration abhaken, um ihre Verbindungen zu beobachten (Leertaste hakt die aktuelle ab). Öffnen oder Bearbeiten einer Konfiguration abonniert nichts; Beobachten abonniert die hier gezählten Topics, insgesamt höchstens %1 Verbindungen.</translation>
    </message>
    <message>
        <source>&amp;Configs (checked: watched)</source>
        <translation>&amp;Konfigurationen (abgehakt: beobachtet)</translation>
    </message>
    <message>
        <source>Watching stopped: %1</source>
        <translation>Beobachtung beendet: %1</translation>
    </message>
    <message>
        <source>No config %1 is open</source>
        <translation>Keine Konfiguration %1 ist offen</translation>
    </message>
    <message>
        <source>Watching %1 refused: %2</source>
        <translation>Beobachten von %1 abgelehnt: %2</translation>
    </message>
    <message>
        <source>not saved yet</source>
        <translation>noch nicht gespeichert</translation>
    </message>
    <message>
        <source>Open a bridge config on the Map page, or add one here; check it to watch it.</source>
        <translation>Öffnen Sie eine Bridge-Konfiguration auf der Seite Zuordnen oder fügen Sie hier eine hinzu; zum Beobachten abhaken.</translation>
    </message>
    <message>
        <source>%1 ROS topics at the master, %2 on the ROS 2 domain and %3 MQTT topics</source>
        <translation>%1 ROS-Topics am Master, %2 in der ROS-2-Domäne und %3 MQTT-Topics</translation>
    </message>
    <message>
        <source>%1 is watched (links: %2): subscribed to %3.</source>
        <translation>%1 wird beobachtet (Verbindungen: %2): abonniert sind %3.</translation>
    </message>
    <message>
        <source>%1 is not watched. Watching it would subscribe to %2 (links: %3).</source>
        <translation>%1 wird nicht beobachtet. Beobachten würde %2 abonnieren (Verbindungen: %3).</translation>
    </message>
    <message>
        <source>That is more than the %1 links a window watches.</source>
        <translation>Das sind mehr als die %1 Verbindungen, die ein Fenster beobachtet.</translation>
    </message>
    <message>
        <source>… and %1 more</source>
        <translation>… und %1 weitere</translation>
    </message>
    <message>
        <source>ROS (master):</source>
        <translation>ROS (Master):</translation>
    </message>
    <message>
        <source>ROS 2:</source>
        <translation>ROS 2:</translation>
    </message>
    <message>
        <source>MQTT:</source>
        <translation>MQTT:</translation>
    </message>
    <message>
        <source>No links watched: check a config below to watch it.</source>
        <translation>Keine Verbindungen beobachtet: unten eine Konfiguration zum Beobachten abhaken.</translation>
    </message>
    <message>
        <source>, %1 unknown (the watch&apos;s own connection is down)</source>
        <translation>, %1 unbekannt (die eigene Verbindung der Beobachtung ist unterbrochen)</translation>
    </message>
    <message>
        <source>This window&apos;s watch</source>
        <translation>Überwachung dieses Fensters</translation>
    </message>
    <message>
        <source>Prometheus server…</source>
        <translation>Prometheus-Server …</translation>
    </message>
    <message>
        <source>Where the links come from: the bridges this window watches itself, or every host&apos;s watch as a Prometheus server has them (nothing subscribed)</source>
        <translation>Woher die Verbindungen kommen: die Bridges, die dieses Fenster selbst überwacht, oder die Überwachungen aller Rechner, wie ein Prometheus-Server sie hat (nichts abonniert)</translation>
    </message>
    <message>
        <source>&amp;Links from:</source>
        <translation>&amp;Verbindungen von:</translation>
    </message>
</context>
<context>
    <name>LiveText</name>
    <message>
        <source>&amp;Copy</source>
        <translation>&amp;Kopieren</translation>
    </message>
</context>
<context>
    <name>LocatedError</name>
    <message>
        <source>line %1: %2</source>
        <translation>Zeile %1: %2</translation>
    </message>
    <message>
        <source>line %1, column %2: %3</source>
        <translation>Zeile %1, Spalte %2: %3</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>Main</name>
    <message>
        <source>bridgescope: the window needs a display, and there is none here (DISPLAY and WAYLAND_DISPLAY are not set).
  On a desktop machine over SSH: ssh -X, or run it on a virtual display: xvfb-run -a bridgescope ...
  Without a window: bridgescope --platform offscreen --screenshot out.png, or one of the commands (bridgescope --help).</source>
        <translation>bridgescope: das Fenster braucht eine Anzeige, und hier gibt es keine (DISPLAY und WAYLAND_DISPLAY sind nicht gesetzt).
  Auf einem Desktop-Rechner über SSH: ssh -X, oder auf einer virtuellen Anzeige ausführen: xvfb-run -a bridgescope ...
  Ohne Fenster: bridgescope --platform offscreen --screenshot out.png, oder einer der Befehle (bridgescope --help).</translation>
    </message>
    <message>
        <source>bridgescope: %1 does not exist</source>
        <translation>bridgescope: %1 gibt es nicht</translation>
    </message>
    <message>
        <source>bridgescope: &apos;%1&apos; is not a command. The commands: %2.</source>
        <translation>bridgescope: &apos;%1&apos; ist kein Befehl. Die Befehle: %2.</translation>
    </message>
    <message>
        <source>Did you mean &apos;%1&apos;?</source>
        <translation>Meinten Sie &apos;%1&apos;?</translation>
    </message>
    <message>
        <source>Run &apos;bridgescope --help&apos; for the options and what each command does.</source>
        <translation>&apos;bridgescope --help&apos; zeigt die Optionen und was jeder Befehl tut.</translation>
    </message>
</context>
<context>
    <name>MainWindow</name>
    <message>
        <source>Map</source>
        <translation>Zuordnen</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>&amp;Neu</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>&amp;Öffnen …</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>Speichern &amp;unter …</translation>
    </message>
    <message>
        <source>&amp;Export As</source>
        <translation>&amp;Exportieren als</translation>
    </message>
    <message>
        <source>mqtt_client, ROS &amp;1…</source>
        <translation>mqtt_client, ROS &amp;1 …</translation>
    </message>
    <message>
        <source>mqtt_client, ROS &amp;2…</source>
        <translation>mqtt_client, ROS &amp;2 …</translation>
    </message>
    <message>
        <source>mqtt_&amp;bridge…</source>
        <translation>mqtt_&amp;bridge …</translation>
    </message>
    <message>
        <source>Generate &amp;Peer Config…</source>
        <translation>&amp;Gegenstellen-Konfiguration erzeugen …</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederholen</translation>
    </message>
    <message>
        <source>&amp;Find Mapping</source>
        <translation>Zuordnung &amp;suchen</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>&amp;About Bridgescope</source>
        <translation>&amp;Über Bridgescope</translation>
    </message>
    <message>
        <source>About Bridgescope</source>
        <translation>Über Bridgescope</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>Über &amp;Qt</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <source>Discover</source>
        <translation>Entdecken</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>Measure</source>
        <translation>Messen</translation>
    </message>
    <message>
        <source>Reports</source>
        <translation>Berichte</translation>
    </message>
    <message>
        <source>&amp;Tools</source>
        <translation>&amp;Extras</translation>
    </message>
    <message>
        <source>Link &amp;Probe…</source>
        <translation>&amp;Streckentest …</translation>
    </message>
    <message>
        <source>Links</source>
        <translation>Verbindungen</translation>
    </message>
    <message>
        <source>untitled</source>
        <translation>unbenannt</translation>
    </message>
    <message>
        <source>Experiments</source>
        <translation>Experimente</translation>
    </message>
    <message>
        <source>Open Run</source>
        <translation>Messlauf öffnen</translation>
    </message>
    <message>
        <source>Experiment running</source>
        <translation>Experiment läuft</translation>
    </message>
    <message>
        <source>An experiment is running. Stop it and quit? Resume goes on with it later.</source>
        <translation>Ein Experiment läuft. Anhalten und beenden? Fortsetzen macht später damit weiter.</translation>
    </message>
    <message>
        <source>&amp;User Guide</source>
        <translation>&amp;Benutzerhandbuch</translation>
    </message>
    <message>
        <source>&amp;Keyboard Shortcuts</source>
        <translation>&amp;Tastenkürzel</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Bridgescope %1&lt;/h3&gt;&lt;p&gt;Discover ROS and MQTT topics, bridge them with mqtt_client, and measure the link.&lt;/p&gt;&lt;p&gt;Built with Qt %2 (running %3), Paho MQTT C++ %4, yaml-cpp %5 and roscpp %6.&lt;/p&gt;&lt;p&gt;MIT License.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Bridgescope %1&lt;/h3&gt;&lt;p&gt;ROS- und MQTT-Topics entdecken, mit mqtt_client verbinden und die Strecke vermessen.&lt;/p&gt;&lt;p&gt;Gebaut mit Qt %2 (läuft mit %3), Paho MQTT C++ %4, yaml-cpp %5 und roscpp %6.&lt;/p&gt;&lt;p&gt;MIT-Lizenz.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Bridgescope User Guide</source>
        <translation>Bridgescope-Benutzerhandbuch</translation>
    </message>
    <message>
        <source>The user guide is missing from this build.</source>
        <translation>Diesem Build fehlt das Benutzerhandbuch.</translation>
    </message>
    <message>
        <source>Button: %1</source>
        <translation>Schaltfläche: %1</translation>
    </message>
    <message>
        <source>Keyboard Shortcuts</source>
        <translation>Tastenkürzel</translation>
    </message>
    <message>
        <source>Command</source>
        <translation>Befehl</translation>
    </message>
    <message>
        <source>Shortcut</source>
        <translation>Tastenkürzel</translation>
    </message>
    <message>
        <source>%1: no such file or folder</source>
        <translation>%1: keine solche Datei und kein solcher Ordner</translation>
    </message>
    <message>
        <source>%1: a folder, but not an experiment&apos;s (it has no experiment plan)</source>
        <translation>%1: ein Ordner, aber nicht der eines Experiments (er hat keinen Experimentplan)</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Öffnen</translation>
    </message>
    <message numerus="yes">
        <source>Could not open %n file(s).</source>
        <translation>
            <numerusform>Eine Datei konnte nicht geöffnet werden.</numerusform>
            <numerusform>%n Dateien konnten nicht geöffnet werden.</numerusform>
        </translation>
    </message>
    <message>
        <source>Bridgescope files (*.yaml *.yml *.bsrun *.csv *.bag);;Bridge configs and pipelines (*.yaml *.yml);;Runs, suite CSV and bags (*.bsrun *.csv *.bag);;All files (*)</source>
        <translation>Bridgescope-Dateien (*.yaml *.yml *.bsrun *.csv *.bag);;Bridge-Konfigurationen und Pipelines (*.yaml *.yml);;Läufe, Suite-CSV und Bags (*.bsrun *.csv *.bag);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>&amp;Theme</source>
        <translation>&amp;Farbschema</translation>
    </message>
    <message>
        <source>&amp;System</source>
        <translation>&amp;System</translation>
    </message>
    <message>
        <source>&amp;Light</source>
        <translation>&amp;Hell</translation>
    </message>
    <message>
        <source>&amp;Dark</source>
        <translation>&amp;Dunkel</translation>
    </message>
    <message>
        <source>broker %1 unreachable</source>
        <translation>Broker %1 nicht erreichbar</translation>
    </message>
    <message>
        <source>&amp;Close Config</source>
        <translation>Konfiguration &amp;schließen</translation>
    </message>
    <message>
        <source>no mappings yet: add one (Insert) or drag topics onto each other</source>
        <translation>noch keine Zuordnungen: eine hinzufügen (Einfg) oder Topics aufeinander ziehen</translation>
    </message>
</context>
<context>
    <name>MapPage</name>
    <message>
        <source>Bridge Selected ROS Topics to MQTT</source>
        <translation>Ausgewählte ROS-Topics nach MQTT übertragen</translation>
    </message>
    <message>
        <source>ROS → MQTT</source>
        <translation>ROS → MQTT</translation>
    </message>
    <message>
        <source>Bridge the selected ROS topics; under the selected MQTT level, if any (Ctrl+Shift+M)</source>
        <translation>Die ausgewählten ROS-Topics übertragen; unter die ausgewählte MQTT-Ebene, falls eine gewählt ist (Strg+Umschalt+M)</translation>
    </message>
    <message>
        <source>Bridge Selected MQTT Topics to ROS</source>
        <translation>Ausgewählte MQTT-Topics nach ROS übertragen</translation>
    </message>
    <message>
        <source>MQTT → ROS</source>
        <translation>MQTT → ROS</translation>
    </message>
    <message>
        <source>Bridge the selected MQTT topics; beside the selected ROS topic, if any (Ctrl+Shift+R)</source>
        <translation>Die ausgewählten MQTT-Topics übertragen; neben das ausgewählte ROS-Topic, falls eines gewählt ist (Strg+Umschalt+R)</translation>
    </message>
    <message>
        <source>Bridge selected:</source>
        <translation>Auswahl übertragen:</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keins</translation>
    </message>
    <message>
        <source>New MQTT topics go below this prefix (for example the client id), unless dropped on a level</source>
        <translation>Neue MQTT-Topics kommen unter dieses Präfix (zum Beispiel die Client-ID), außer sie werden auf eine Ebene gezogen</translation>
    </message>
    <message>
        <source>MQTT &amp;prefix:</source>
        <translation>MQTT-&amp;Präfix:</translation>
    </message>
    <message>
        <source>Filter ROS topics…</source>
        <translation>ROS-Topics filtern …</translation>
    </message>
    <message>
        <source>Filter MQTT topics…</source>
        <translation>MQTT-Topics filtern …</translation>
    </message>
    <message>
        <source>Bridge %1 to MQTT</source>
        <translation>%1 nach MQTT übertragen</translation>
    </message>
    <message>
        <source>Bridge %1 ROS topics to MQTT</source>
        <translation>%1 ROS-Topics nach MQTT übertragen</translation>
    </message>
    <message>
        <source>Bridge %1 to ROS</source>
        <translation>%1 nach ROS übertragen</translation>
    </message>
    <message>
        <source>Bridge %1 MQTT topics to ROS</source>
        <translation>%1 MQTT-Topics nach ROS übertragen</translation>
    </message>
    <message>
        <source>Retarget to %1</source>
        <translation>Auf %1 umlenken</translation>
    </message>
    <message>
        <source>Discovered Topics</source>
        <translation>Gefundene Topics</translation>
    </message>
    <message>
        <source>Show or fold away the discovered ROS and MQTT topics (Ctrl+Shift+T)</source>
        <translation>Die gefundenen ROS- und MQTT-Topics zeigen oder einklappen (Strg+Umschalt+T)</translation>
    </message>
    <message>
        <source>Drag ROS topics onto the MQTT tree, MQTT topics onto a ROS namespace (or onto one ROS topic to publish there); drop a topic on a mapping to retarget it.</source>
        <translation>Ziehen Sie ROS-Topics auf den MQTT-Baum, MQTT-Topics auf einen ROS-Namensraum (oder auf ein ROS-Topic, um dorthin zu veröffentlichen); ein Topic auf einer Zuordnung ändert deren Ziel.</translation>
    </message>
</context>
<context>
    <name>MappingHealth</name>
    <message>
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
    <message>
        <source>no publisher</source>
        <translation>kein Publisher</translation>
    </message>
    <message>
        <source>silent</source>
        <translation>still</translation>
    </message>
    <message>
        <source>never seen</source>
        <translation>nie gesehen</translation>
    </message>
    <message>
        <source>ROS master not reachable</source>
        <translation>ROS-Master nicht erreichbar</translation>
    </message>
    <message>
        <source>broker not connected</source>
        <translation>Broker nicht verbunden</translation>
    </message>
    <message>
        <source>Connect to the ROS master and the broker on the Discover page to see this mapping&apos;s traffic.</source>
        <translation>Auf der Seite Entdecken mit ROS-Master und Broker verbinden, um den Verkehr dieser Zuordnung zu sehen.</translation>
    </message>
    <message>
        <source>ROS topic not on the master</source>
        <translation>ROS-Topic nicht beim Master</translation>
    </message>
    <message>
        <source>Nobody publishes or subscribes &apos;%1&apos; on this master.</source>
        <translation>Niemand veröffentlicht oder abonniert &apos;%1&apos; bei diesem Master.</translation>
    </message>
    <message>
        <source>no publisher on ROS</source>
        <translation>kein Publisher auf ROS</translation>
    </message>
    <message>
        <source>&apos;%1&apos; exists but nobody publishes it, so there is nothing to bridge.</source>
        <translation>&apos;%1&apos; gibt es, aber niemand veröffentlicht es; es gibt nichts zu übertragen.</translation>
    </message>
    <message>
        <source>no bridge running?</source>
        <translation>keine Bridge aktiv?</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is published (%2) but nothing arrived on &apos;%3&apos; in the last %4 s.</source>
        <translation>&apos;%1&apos; wird veröffentlicht (%2), aber auf &apos;%3&apos; kam in den letzten %4 s nichts an.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; (%2) arrives on &apos;%3&apos; (%4).</source>
        <translation>&apos;%1&apos; (%2) kommt auf &apos;%3&apos; an (%4).</translation>
    </message>
    <message>
        <source>MQTT topic never seen</source>
        <translation>MQTT-Topic nie gesehen</translation>
    </message>
    <message>
        <source>Nothing has been published on &apos;%1&apos; since Bridgescope connected.</source>
        <translation>Auf &apos;%1&apos; wurde nichts veröffentlicht, seit Bridgescope verbunden ist.</translation>
    </message>
    <message>
        <source>MQTT topic silent</source>
        <translation>MQTT-Topic still</translation>
    </message>
    <message>
        <source>&apos;%1&apos; has been silent for %2 s.</source>
        <translation>&apos;%1&apos; ist seit %2 s still.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; carries %2 but nobody publishes &apos;%3&apos; on ROS.</source>
        <translation>&apos;%1&apos; trägt %2, aber niemand veröffentlicht &apos;%3&apos; auf ROS.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; (%2) is published on &apos;%3&apos; (%4).</source>
        <translation>&apos;%1&apos; (%2) wird auf &apos;%3&apos; veröffentlicht (%4).</translation>
    </message>
    <message>
        <source>type mismatch</source>
        <translation>Typen passen nicht</translation>
    </message>
    <message>
        <source>The broker announces &apos;%1&apos; for &apos;%2&apos;, but &apos;%3&apos; has type &apos;%4&apos; on ROS.</source>
        <translation>Der Broker kündigt &apos;%1&apos; für &apos;%2&apos; an, aber &apos;%3&apos; hat auf ROS den Typ &apos;%4&apos;.</translation>
    </message>
    <message>
        <source>publishers: %1</source>
        <translation>Publisher: %1</translation>
    </message>
    <message>
        <source>%1 publishes %2: %3</source>
        <translation>%1 veröffentlicht mit %2: %3</translation>
    </message>
    <message>
        <source>a node</source>
        <translation>ein Knoten</translation>
    </message>
    <message>
        <source>%1 subscribes with %2: %3</source>
        <translation>%1 abonniert mit %2: %3</translation>
    </message>
    <message>
        <source>ROS 2 domain not joined</source>
        <translation>ROS-2-Domäne nicht beigetreten</translation>
    </message>
    <message>
        <source>ROS 2 topic not in the graph</source>
        <translation>ROS-2-Topic nicht im Graphen</translation>
    </message>
    <message>
        <source>Nobody publishes or subscribes &apos;%1&apos; on this ROS 2 domain.</source>
        <translation>Niemand veröffentlicht oder abonniert „%1“ in dieser ROS-2-Domäne.</translation>
    </message>
    <message>
        <source>QoS incompatible</source>
        <translation>QoS unverträglich</translation>
    </message>
    <message>
        <source>mqtt_client&apos;s subscription to &apos;%1&apos; cannot match a publisher: %2. Set advanced.ros.qos to auto or to what the publishers offer.</source>
        <translation>Das Abonnement von mqtt_client auf „%1“ passt zu keinem Publisher: %2. Setzen Sie advanced.ros.qos auf auto oder auf das, was die Publisher bieten.</translation>
    </message>
    <message>
        <source>Subscribers of &apos;%1&apos; cannot get mqtt_client&apos;s messages: %2. Offer at least what they ask for in advanced.ros.qos.</source>
        <translation>Subscriber von „%1“ erhalten die Nachrichten von mqtt_client nicht: %2. Bieten Sie in advanced.ros.qos mindestens, was sie verlangen.</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>Last one-way latency on the broker: %1 ms.</source>
        <translation>Letzte Einweg-Latenz am Broker: %1 ms.</translation>
    </message>
    <message>
        <source>Over the same %1 s, %2 messages were published on &apos;%3&apos; and %4 arrived on &apos;%5&apos;.</source>
        <translation>In denselben %1 s wurden %2 Nachrichten auf &apos;%3&apos; veröffentlicht und %4 kamen auf &apos;%5&apos; an.</translation>
    </message>
    <message>
        <source>One message in flight at the interval&apos;s edge is counted on one side only.</source>
        <translation>Eine Nachricht, die am Rand des Intervalls unterwegs ist, wird nur auf einer Seite gezählt.</translation>
    </message>
    <message>
        <source>More arrive than are published: does something else publish on &apos;%1&apos; too?</source>
        <translation>Es kommen mehr an, als veröffentlicht werden: veröffentlicht noch etwas anderes auf &apos;%1&apos;?</translation>
    </message>
</context>
<context>
    <name>MappingInspector</name>
    <message>
        <source>Select a mapping to edit it, or add one with Insert.</source>
        <translation>Eine Zuordnung auswählen, um sie zu bearbeiten, oder mit Einfg eine hinzufügen.</translation>
    </message>
    <message>
        <source>&amp;Direction</source>
        <translation>&amp;Richtung</translation>
    </message>
    <message>
        <source>&amp;ROS topic</source>
        <translation>&amp;ROS-Topic</translation>
    </message>
    <message>
        <source>M&amp;QTT topic</source>
        <translation>M&amp;QTT-Topic</translation>
    </message>
    <message>
        <source>Set %1</source>
        <translation>%1 setzen</translation>
    </message>
    <message>
        <source>%1 mappings selected: a change applies to all of them.</source>
        <translation>%1 Zuordnungen ausgewählt: Eine Änderung gilt für alle.</translation>
    </message>
    <message>
        <source>e.g. /vehicle/points</source>
        <translation>z. B. /vehicle/points</translation>
    </message>
    <message>
        <source>(several)</source>
        <translation>(mehrere)</translation>
    </message>
    <message>
        <source>e.g. vehicle/points</source>
        <translation>z. B. vehicle/points</translation>
    </message>
    <message>
        <source>Error: %1</source>
        <translation>Fehler: %1</translation>
    </message>
    <message>
        <source>Warning: %1</source>
        <translation>Warnung: %1</translation>
    </message>
    <message>
        <source>Problems in the selection: %1</source>
        <translation>Probleme in der Auswahl: %1</translation>
    </message>
    <message>
        <source>%1 on %2 mappings</source>
        <translation>%1 für %2 Zuordnungen</translation>
    </message>
    <message>
        <source>Set ROS topic</source>
        <translation>ROS-Topic setzen</translation>
    </message>
    <message>
        <source>Set MQTT topic</source>
        <translation>MQTT-Topic setzen</translation>
    </message>
    <message>
        <source>Change direction</source>
        <translation>Richtung ändern</translation>
    </message>
</context>
<context>
    <name>MappingModel</name>
    <message>
        <source>ROS → MQTT</source>
        <translation>ROS → MQTT</translation>
    </message>
    <message>
        <source>MQTT → ROS</source>
        <translation>MQTT → ROS</translation>
    </message>
    <message>
        <source>primitive</source>
        <translation>primitiv</translation>
    </message>
    <message>
        <source>JSON</source>
        <translation>JSON</translation>
    </message>
    <message>
        <source>stamped</source>
        <translation>mit Zeitstempel</translation>
    </message>
    <message>
        <source>QoS %1</source>
        <translation>QoS %1</translation>
    </message>
    <message>
        <source>retained</source>
        <translation>retained</translation>
    </message>
    <message>
        <source>latched</source>
        <translation>latched</translation>
    </message>
    <message>
        <source>queue %1</source>
        <translation>Warteschlange %1</translation>
    </message>
    <message>
        <source>suite stamps</source>
        <translation>Suite-Zeitstempel</translation>
    </message>
    <message>
        <source>Direction</source>
        <translation>Richtung</translation>
    </message>
    <message>
        <source>ROS topic</source>
        <translation>ROS-Topic</translation>
    </message>
    <message>
        <source>MQTT topic</source>
        <translation>MQTT-Topic</translation>
    </message>
    <message>
        <source>Options</source>
        <translation>Optionen</translation>
    </message>
    <message>
        <source>Health</source>
        <translation>Zustand</translation>
    </message>
</context>
<context>
    <name>MeasurePage</name>
    <message>
        <source>&amp;Log scale</source>
        <translation>&amp;Logarithmisch</translation>
    </message>
    <message>
        <source>Small &amp;multiples</source>
        <translation>&amp;Einzeldiagramme</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>&amp;Pause</translation>
    </message>
    <message>
        <source>&amp;Reset</source>
        <translation>&amp;Zurücksetzen</translation>
    </message>
    <message>
        <source>L&amp;oad Pipeline…</source>
        <translation>Pipeline &amp;laden …</translation>
    </message>
    <message>
        <source>&amp;Save Pipeline…</source>
        <translation>Pipeline &amp;speichern …</translation>
    </message>
    <message>
        <source>&amp;Automatic</source>
        <translation>&amp;Automatisch</translation>
    </message>
    <message>
        <source>Find the pipeline in the stamps that arrive: every stamp topic, ordered by its mean time within the samples, hosts guessed from the names</source>
        <translation>Die Pipeline in den eintreffenden Zeitstempeln finden: jedes Zeitstempel-Topic, geordnet nach seiner mittleren Zeit innerhalb der Proben, Rechner aus den Namen geraten</translation>
    </message>
    <message>
        <source>whole run</source>
        <translation>ganzer Lauf</translation>
    </message>
    <message>
        <source> samples</source>
        <translation> Proben</translation>
    </message>
    <message>
        <source>Statistics and ECDFs over the last N complete samples (the paper: 600), or 0 for the whole run</source>
        <translation>Statistik und ECDFs über die letzten N vollständigen Proben (im Paper: 600), oder 0 für den ganzen Lauf</translation>
    </message>
    <message>
        <source>&amp;Window:</source>
        <translation>&amp;Fenster:</translation>
    </message>
    <message>
        <source>Freeze the chart and the table; measuring goes on (Ctrl+P)</source>
        <translation>Diagramm und Tabelle anhalten; gemessen wird weiter (Strg+P)</translation>
    </message>
    <message>
        <source>Forget every sample and count; keep the pipeline (Ctrl+R)</source>
        <translation>Alle Proben und Zähler vergessen; die Pipeline bleibt (Strg+R)</translation>
    </message>
    <message>
        <source>Remove from Pipeline</source>
        <translation>Aus der Pipeline entfernen</translation>
    </message>
    <message>
        <source>Move Up</source>
        <translation>Nach oben</translation>
    </message>
    <message>
        <source>Move Down</source>
        <translation>Nach unten</translation>
    </message>
    <message>
        <source>Drag a stamp topic into the pipeline, or press Enter to append it</source>
        <translation>Ein Zeitstempel-Topic in die Pipeline ziehen oder mit Eingabe anhängen</translation>
    </message>
    <message>
        <source>&lt;b&gt;Pipeline&lt;/b&gt;: stamp topics in the order a sample passes them</source>
        <translation>&lt;b&gt;Pipeline&lt;/b&gt;: Zeitstempel-Topics in der Reihenfolge, in der eine Probe sie durchläuft</translation>
    </message>
    <message>
        <source>Automatic: waiting for stamps (benchmarking_suite/TimeStamped on ROS or MQTT, or JSON stamps on MQTT).</source>
        <translation>Automatisch: warte auf Zeitstempel (benchmarking_suite/TimeStamped über ROS oder MQTT, oder JSON-Zeitstempel über MQTT).</translation>
    </message>
    <message>
        <source>Automatic: ordered by the stamps&apos; times, hosts guessed from the names. Drag rows to reorder, double-click a host to change it.</source>
        <translation>Automatisch: nach den Zeiten der Zeitstempel geordnet, Rechner aus den Namen geraten. Zeilen ziehen zum Umordnen, Rechner doppelklicken zum Ändern.</translation>
    </message>
    <message>
        <source>From %1.</source>
        <translation>Aus %1.</translation>
    </message>
    <message>
        <source>Edited by hand.</source>
        <translation>Von Hand bearbeitet.</translation>
    </message>
    <message>
        <source>Samples: %1 complete · %2 dropped · %3 incomplete · %4 duplicate stamps · %5 from unknown topics</source>
        <translation>Proben: %1 vollständig · %2 verworfen · %3 unvollständig · %4 doppelte Zeitstempel · %5 von unbekannten Topics</translation>
    </message>
    <message>
        <source> · paused</source>
        <translation> · angehalten</translation>
    </message>
    <message>
        <source>Load Pipeline</source>
        <translation>Pipeline laden</translation>
    </message>
    <message>
        <source>Pipelines (*.yaml *.yml);;All files (*)</source>
        <translation>Pipelines (*.yaml *.yml);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Save Pipeline</source>
        <translation>Pipeline speichern</translation>
    </message>
    <message>
        <source>Pipelines (*.yaml *.yml)</source>
        <translation>Pipelines (*.yaml *.yml)</translation>
    </message>
    <message>
        <source>Save the chart as PNG or SVG</source>
        <translation>Das Diagramm als PNG oder SVG speichern</translation>
    </message>
    <message>
        <source>Cop&amp;y Chart</source>
        <translation>Diagramm &amp;kopieren</translation>
    </message>
    <message>
        <source>Copy the chart to the clipboard as an image</source>
        <translation>Das Diagramm als Bild in die Zwischenablage kopieren</translation>
    </message>
    <message>
        <source>SVG (*.svg);;PNG (*.png)</source>
        <translation>SVG (*.svg);;PNG (*.png)</translation>
    </message>
    <message>
        <source>The recorded run&apos;s pipeline.</source>
        <translation>Die Pipeline des aufgezeichneten Laufs.</translation>
    </message>
    <message>
        <source>E&amp;xport Chart…</source>
        <translation>Diagramm e&amp;xportieren …</translation>
    </message>
    <message>
        <source>Stamp &amp;topics seen:</source>
        <translation>Gesehene Zeitstempel-&amp;Topics:</translation>
    </message>
    <message>
        <source>Export Chart</source>
        <translation>Diagramm exportieren</translation>
    </message>
    <message>
        <source>%1 on %2</source>
        <translation>%1 auf %2</translation>
    </message>
    <message numerus="yes">
        <source>%n more topic(s)</source>
        <translation>
            <numerusform>%n weiteres Topic</numerusform>
            <numerusform>%n weitere Topics</numerusform>
        </translation>
    </message>
    <message>
        <source> · %1 malformed: %2 (last: %3)</source>
        <translation> · %1 fehlerhaft: %2 (zuletzt: %3)</translation>
    </message>
    <message numerus="yes">
        <source> · %n begun before every stamp topic was heard</source>
        <translation>
            <numerusform> · %n begonnen, bevor jedes Zeitstempel-Topic zu hören war</numerusform>
            <numerusform> · %n begonnen, bevor jedes Zeitstempel-Topic zu hören war</numerusform>
        </translation>
    </message>
    <message>
        <source> · waiting for the first stamp of %1</source>
        <translation> · wartet auf den ersten Zeitstempel von %1</translation>
    </message>
    <message>
        <source>Not a measurement:</source>
        <translation>Keine Messung:</translation>
    </message>
    <message>
        <source>%1 or %2.</source>
        <translation>%1 oder %2.</translation>
    </message>
    <message>
        <source>Set hosts</source>
        <translation>Hosts setzen</translation>
    </message>
    <message>
        <source>load a pipeline</source>
        <translation>eine Pipeline laden</translation>
    </message>
    <message>
        <source>Each host&apos;s clock against the pipeline&apos;s first host, from the clock service&apos;s probes: the crossings between measured hosts are corrected by it (rows &quot;clocks measured&quot;), each within the uncertainty shown.</source>
        <translation>Die Uhr jedes Rechners gegenüber dem ersten Rechner der Pipeline, aus den Proben des Uhrendienstes: Übergänge zwischen gemessenen Rechnern werden damit korrigiert (Zeilen „Uhren gemessen“), jeweils auf die angezeigte Unsicherheit genau.</translation>
    </message>
    <message numerus="yes">
        <source> · the observed hop latency of %n more link(s) is on the Links page only (the first links to match have a series here, a bounded number)</source>
        <translation>
            <numerusform> · die beobachtete Sprunglatenz %n weiteren Verbindung steht nur auf der Seite Verbindungen (die ersten zugeordneten Verbindungen haben hier eine Reihe, in begrenzter Zahl)</numerusform>
            <numerusform> · die beobachtete Sprunglatenz %n weiterer Verbindungen steht nur auf der Seite Verbindungen (die ersten zugeordneten Verbindungen haben hier eine Reihe, in begrenzter Zahl)</numerusform>
        </translation>
    </message>
    <message>
        <source> · %1 observed hop latencies dropped unmeasured (more came between two reads than a link keeps)</source>
        <translation> · %1 beobachtete Sprunglatenzen ungemessen verworfen (zwischen zwei Lesevorgängen kamen mehr, als eine Verbindung behält)</translation>
    </message>
    <message numerus="yes">
        <source> · %n observed hop(s) without stamps: the last rows of the stage table</source>
        <translation>
            <numerusform> · %n beobachteter Hop ohne Stempel: die letzte Zeile der Stufentabelle</numerusform>
            <numerusform> · %n beobachtete Hops ohne Stempel: die letzten Zeilen der Stufentabelle</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>MeasureSession</name>
    <message>
        <source>a recorded run is on screen: go back to live first</source>
        <translation>ein aufgezeichneter Lauf wird angezeigt: zuerst zurück zu Live</translation>
    </message>
    <message>
        <source>no pipeline yet: load one, or wait until stamps arrive</source>
        <translation>noch keine Pipeline: eine laden oder warten, bis Zeitstempel eintreffen</translation>
    </message>
    <message>
        <source>recording: stop it before opening a run</source>
        <translation>Aufzeichnung läuft: vor dem Öffnen eines Laufs beenden</translation>
    </message>
    <message>
        <source>domain %1, this host only</source>
        <translation>Domäne %1, nur dieser Rechner</translation>
    </message>
    <message>
        <source>domain %1</source>
        <translation>Domain %1</translation>
    </message>
    <message>
        <source>Clocks measured: %1.</source>
        <translation>Uhren gemessen: %1.</translation>
    </message>
    <message>
        <source>Measuring the clocks of %1 through the broker (bridgescope clock serve on each host)…</source>
        <translation>Messe die Uhren von %1 über den Broker (bridgescope clock serve auf jedem Rechner) …</translation>
    </message>
</context>
<context>
    <name>MetricsServer</name>
    <message>
        <source>&apos;%1&apos; is not HOST:PORT (for example 127.0.0.1:9464, [::1]:9464, or :9464 for every interface)</source>
        <translation>&apos;%1&apos; ist nicht HOST:PORT (zum Beispiel 127.0.0.1:9464, [::1]:9464 oder :9464 für alle Schnittstellen)</translation>
    </message>
    <message>
        <source>cannot serve metrics on %1: %2</source>
        <translation>Metriken können nicht auf %1 bereitgestellt werden: %2</translation>
    </message>
</context>
<context>
    <name>MqttClientReleases</name>
    <message>
        <source>the ROS 1 layout (up to %1)</source>
        <translation>das ROS-1-Layout (bis %1)</translation>
    </message>
    <message>
        <source>a primitive %1</source>
        <translation>ein Primitive %1</translation>
    </message>
    <message>
        <source>an mqtt_bridge config: no release of mqtt_client loads it</source>
        <translation>eine mqtt_bridge-Konfiguration: kein Release von mqtt_client lädt sie</translation>
    </message>
    <message>
        <source>no release loads all of it</source>
        <translation>kein Release lädt sie ganz</translation>
    </message>
    <message>
        <source>it loads in %1 only</source>
        <translation>sie lädt nur in %1</translation>
    </message>
    <message>
        <source>it loads in %1 to %2</source>
        <translation>sie lädt in %1 bis %2</translation>
    </message>
    <message>
        <source>checked against mqtt_client %1%2; %3%4</source>
        <translation>geprüft gegen mqtt_client %1%2; %3%4</translation>
    </message>
    <message>
        <source> (auto)</source>
        <translation> (auto)</translation>
    </message>
</context>
<context>
    <name>MqttClientWire</name>
    <message>
        <source>type announcement ends before the length of &apos;%1&apos; (byte %2)</source>
        <translation>Typankündigung endet vor der Länge von &apos;%1&apos; (Byte %2)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; claims %2 bytes but only %3 follow</source>
        <translation>&apos;%1&apos; gibt %2 Bytes an, es folgen aber nur %3</translation>
    </message>
    <message>
        <source>type announcement has %1 bytes after the strings, expected 1 (stamped)</source>
        <translation>Typankündigung hat %1 Bytes nach den Zeichenketten, erwartet 1 (stamped)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not an MD5 sum</source>
        <translation>&apos;%1&apos; ist keine MD5-Summe</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a ROS type name</source>
        <translation>&apos;%1&apos; ist kein ROS-Typname</translation>
    </message>
    <message>
        <source>type announcement of %1 bytes, more than the %2 one may have</source>
        <translation>Typankündigung mit %1 Bytes, mehr als die erlaubten %2</translation>
    </message>
    <message>
        <source>ROS 2 type announcement of %1 bytes ends inside its CDR encapsulation header</source>
        <translation>ROS-2-Typankündigung mit %1 Bytes endet innerhalb ihres CDR-Kapselungskopfs</translation>
    </message>
    <message>
        <source>ROS 2 type announcement is not plain CDR (encapsulation %1 %2)</source>
        <translation>ROS-2-Typankündigung ist kein einfaches CDR (Kapselung %1 %2)</translation>
    </message>
    <message>
        <source>type announcement ends before &apos;stamped&apos; (byte %1)</source>
        <translation>Typankündigung endet vor &apos;stamped&apos; (Byte %1)</translation>
    </message>
    <message>
        <source>type announcement has %1 bytes after &apos;stamped&apos;, more than CDR&apos;s padding of at most 3</source>
        <translation>Typankündigung hat %1 Bytes nach &apos;stamped&apos;, mehr als die höchstens 3 Füllbytes von CDR</translation>
    </message>
    <message>
        <source>stamped payload of %1 bytes, shorter than its %2-byte stamp</source>
        <translation>Nutzlast mit Zeitstempel hat %1 Bytes, weniger als ihr %2-Byte-Zeitstempel</translation>
    </message>
    <message>
        <source>the stamp does not start with a CDR encapsulation header (%1 %2)</source>
        <translation>der Zeitstempel beginnt nicht mit einem CDR-Kapselungskopf (%1 %2)</translation>
    </message>
    <message>
        <source>the stamp has %1 nanoseconds, not fewer than 1000000000</source>
        <translation>der Zeitstempel hat %1 Nanosekunden, nicht weniger als 1000000000</translation>
    </message>
</context>
<context>
    <name>MqttClockProber</name>
    <message>
        <source>&apos;%1&apos; cannot name a host (1 to 64 bytes without spaces, &apos;/&apos;, &apos;+&apos; or &apos;#&apos;)</source>
        <translation>„%1“ kann keinen Rechner benennen (1 bis 64 Bytes ohne Leerzeichen, „/“, „+“ oder „#“)</translation>
    </message>
</context>
<context>
    <name>MqttConnection</name>
    <message>
        <source>the broker does not speak this MQTT version</source>
        <translation>der Broker spricht diese MQTT-Version nicht</translation>
    </message>
    <message>
        <source>the broker rejected the client id</source>
        <translation>der Broker lehnt die Client-ID ab</translation>
    </message>
    <message>
        <source>the broker is unavailable</source>
        <translation>der Broker ist nicht verfügbar</translation>
    </message>
    <message>
        <source>the broker refused the user name or password</source>
        <translation>der Broker lehnt Benutzername oder Passwort ab</translation>
    </message>
    <message>
        <source>the client is not authorised to connect</source>
        <translation>der Client darf sich nicht verbinden</translation>
    </message>
    <message>
        <source>no broker answers at %1</source>
        <translation>unter %1 antwortet kein Broker</translation>
    </message>
    <message>
        <source>cannot connect to %1 (Paho error %2)</source>
        <translation>keine Verbindung zu %1 (Paho-Fehler %2)</translation>
    </message>
    <message>
        <source>disconnected</source>
        <translation>getrennt</translation>
    </message>
    <message>
        <source>connecting</source>
        <translation>verbinde</translation>
    </message>
    <message>
        <source>connected</source>
        <translation>verbunden</translation>
    </message>
    <message>
        <source>reconnecting</source>
        <translation>verbinde erneut</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>fehlgeschlagen</translation>
    </message>
    <message>
        <source>%1; retrying in %2 s</source>
        <translation>%1; neuer Versuch in %2 s</translation>
    </message>
    <message>
        <source>connection lost</source>
        <translation>Verbindung verloren</translation>
    </message>
    <message>
        <source>cannot connect to %1: %2</source>
        <translation>keine Verbindung zu %1: %2</translation>
    </message>
    <message>
        <source>%1; reconnecting</source>
        <translation>%1; verbinde erneut</translation>
    </message>
    <message>
        <source>TLS failed: %1</source>
        <translation>TLS fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>not connected to the broker</source>
        <translation>keine Verbindung zum Broker</translation>
    </message>
</context>
<context>
    <name>MqttLink</name>
    <message>
        <source>no answer from %1 within %2 s</source>
        <translation>keine Antwort von %1 binnen %2 s</translation>
    </message>
    <message>
        <source>cannot connect to %1: %2</source>
        <translation>keine Verbindung zu %1: %2</translation>
    </message>
    <message>
        <source>no broker answers at %1</source>
        <translation>unter %1 antwortet kein Broker</translation>
    </message>
    <message>
        <source>the broker at %1 does not confirm the subscription to %2</source>
        <translation>der Broker unter %1 bestätigt das Abonnement von %2 nicht</translation>
    </message>
    <message>
        <source>the broker at %1 refuses the subscription to %2: %3</source>
        <translation>der Broker unter %1 lehnt das Abonnement von %2 ab: %3</translation>
    </message>
    <message>
        <source>cannot publish on %1: %2</source>
        <translation>auf %1 lässt sich nicht veröffentlichen: %2</translation>
    </message>
</context>
<context>
    <name>MqttProfile</name>
    <message>
        <source>&apos;%1&apos; is not a broker URL; write it as tcp://host:1883 or ssl://host:8883.</source>
        <translation>&apos;%1&apos; ist keine Broker-URL; als tcp://host:1883 oder ssl://host:8883 schreiben.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a broker scheme; use tcp, ssl, mqtt, mqtts, ws or wss.</source>
        <translation>&apos;%1&apos; ist kein Broker-Schema; tcp, ssl, mqtt, mqtts, ws oder wss verwenden.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; names no host.</source>
        <translation>&apos;%1&apos; nennt keinen Host.</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: port 0 is not a port.</source>
        <translation>&apos;%1&apos;: Port 0 ist kein Port.</translation>
    </message>
    <message>
        <source>MQTT version must be 3.1.1 (4) or 5.</source>
        <translation>Die MQTT-Version muss 3.1.1 (4) oder 5 sein.</translation>
    </message>
    <message>
        <source>Subscribe at least one topic filter, e.g. #.</source>
        <translation>Mindestens einen Topic-Filter abonnieren, z. B. #.</translation>
    </message>
    <message>
        <source>Filter &apos;%1&apos;: %2.</source>
        <translation>Filter &apos;%1&apos;: %2.</translation>
    </message>
    <message>
        <source>A client certificate needs its key file.</source>
        <translation>Ein Client-Zertifikat braucht seine Schlüsseldatei.</translation>
    </message>
</context>
<context>
    <name>MqttProfileDialog</name>
    <message>
        <source>Broker Connection</source>
        <translation>Broker-Verbindung</translation>
    </message>
    <message>
        <source>tcp://, mqtt:// (plain), ssl://, mqtts:// (TLS), ws://, wss:// (WebSocket)</source>
        <translation>tcp://, mqtt:// (unverschlüsselt), ssl://, mqtts:// (TLS), ws://, wss:// (WebSocket)</translation>
    </message>
    <message>
        <source>random bridgescope-… id</source>
        <translation>zufällige bridgescope-…-ID</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Start a clean session</source>
        <translation>Eine frische Sitzung beginnen</translation>
    </message>
    <message>
        <source>Keep the password in the system keyring (never in a file)</source>
        <translation>Das Passwort im Schlüsselbund des Systems aufbewahren (nie in einer Datei)</translation>
    </message>
    <message>
        <source>CA certificate</source>
        <translation>CA-Zertifikat</translation>
    </message>
    <message>
        <source>Client certificate</source>
        <translation>Client-Zertifikat</translation>
    </message>
    <message>
        <source>Client key</source>
        <translation>Client-Schlüssel</translation>
    </message>
    <message>
        <source>Verify the broker&apos;s certificate and host name</source>
        <translation>Zertifikat und Hostnamen des Brokers prüfen</translation>
    </message>
    <message>
        <source>Topic filters to subscribe, separated by commas; # subscribes to everything.</source>
        <translation>Zu abonnierende Topic-Filter, durch Kommas getrennt; # abonniert alles.</translation>
    </message>
    <message>
        <source>Also subscribe $SYS/# (broker statistics)</source>
        <translation>Auch $SYS/# abonnieren (Broker-Kennzahlen)</translation>
    </message>
    <message>
        <source> messages per topic</source>
        <translation> Nachrichten je Topic</translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation>&amp;Name:</translation>
    </message>
    <message>
        <source>&amp;URL:</source>
        <translation>&amp;URL:</translation>
    </message>
    <message>
        <source>&amp;Protocol:</source>
        <translation>&amp;Protokoll:</translation>
    </message>
    <message>
        <source>&amp;Client id:</source>
        <translation>&amp;Client-ID:</translation>
    </message>
    <message>
        <source>&amp;Keep-alive:</source>
        <translation>&amp;Keep-Alive:</translation>
    </message>
    <message>
        <source>&amp;User:</source>
        <translation>&amp;Benutzer:</translation>
    </message>
    <message>
        <source>Pass&amp;word:</source>
        <translation>Pass&amp;wort:</translation>
    </message>
    <message>
        <source>C&amp;A file:</source>
        <translation>C&amp;A-Datei:</translation>
    </message>
    <message>
        <source>Cer&amp;tificate:</source>
        <translation>Zer&amp;tifikat:</translation>
    </message>
    <message>
        <source>&amp;Key file:</source>
        <translation>&amp;Schlüsseldatei:</translation>
    </message>
    <message>
        <source>Key pass&amp;word:</source>
        <translation>Schlüssel-Pass&amp;wort:</translation>
    </message>
    <message>
        <source>&amp;Subscribe:</source>
        <translation>&amp;Abonnieren:</translation>
    </message>
    <message>
        <source>&amp;History:</source>
        <translation>&amp;Verlauf:</translation>
    </message>
    <message>
        <source>Choose a file</source>
        <translation>Datei wählen</translation>
    </message>
</context>
<context>
    <name>MqttStampDecoder</name>
    <message>
        <source>type announcement: %1</source>
        <translation>Typankündigung: %1</translation>
    </message>
</context>
<context>
    <name>MqttTopicTree</name>
    <message>
        <source>(empty level)</source>
        <translation>(leere Ebene)</translation>
    </message>
    <message>
        <source>retained</source>
        <translation>retained</translation>
    </message>
    <message>
        <source>malformed type announcement</source>
        <translation>fehlerhafte Typankündigung</translation>
    </message>
    <message>
        <source> (stamped)</source>
        <translation> (mit Zeitstempel)</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>Receive time minus the stamp mqtt_client injected on the sending host: valid only as far as the two clocks agree.</source>
        <translation>Empfangszeit minus dem Zeitstempel, den mqtt_client beim Sender eingefügt hat: nur so genau, wie die beiden Uhren übereinstimmen.</translation>
    </message>
    <message>
        <source>Topic</source>
        <translation>Topic</translation>
    </message>
    <message>
        <source>Messages</source>
        <translation>Nachrichten</translation>
    </message>
    <message>
        <source>Rate (Hz)</source>
        <translation>Rate (Hz)</translation>
    </message>
    <message>
        <source>Bytes</source>
        <translation>Bytes</translation>
    </message>
    <message>
        <source>Last size</source>
        <translation>Letzte Größe</translation>
    </message>
    <message>
        <source>Retained</source>
        <translation>Retained</translation>
    </message>
    <message>
        <source>QoS</source>
        <translation>QoS</translation>
    </message>
    <message>
        <source>Last message</source>
        <translation>Letzte Nachricht</translation>
    </message>
    <message>
        <source>ROS type</source>
        <translation>ROS-Typ</translation>
    </message>
    <message>
        <source>Latency</source>
        <translation>Latenz</translation>
    </message>
    <message>
        <source>the definition of %1 does not read: %2</source>
        <translation>die Definition von %1 ist nicht lesbar: %2</translation>
    </message>
    <message>
        <source>%1
%2 payloads did not decode; the last: %3</source>
        <translation>%1
%2 Nutzlasten ließen sich nicht dekodieren; die letzte: %3</translation>
    </message>
    <message>
        <source>No ROS 2 definition of %1 is known: its payloads show raw.</source>
        <translation>Für %1 ist keine ROS-2-Definition bekannt: seine Nutzdaten werden roh gezeigt.</translation>
    </message>
    <message>
        <source>(empty)</source>
        <translation>(leer)</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
</context>
<context>
    <name>NameDelegate</name>
    <message>
        <source>%1 in %2</source>
        <translation>%1 in %2</translation>
    </message>
    <message>
        <source>Every name below starts with %1</source>
        <translation>Jeder Name darunter beginnt mit %1</translation>
    </message>
</context>
<context>
    <name>NameHeader</name>
    <message>
        <source>%1 in %2</source>
        <translation>%1 in %2</translation>
    </message>
</context>
<context>
    <name>OptionForm</name>
    <message>
        <source>benchmarking suite</source>
        <translation>Benchmarking-Suite</translation>
    </message>
    <message>
        <source>general</source>
        <translation>allgemein</translation>
    </message>
    <message>
        <source>Default: %1</source>
        <translation>Vorgabe: %1</translation>
    </message>
    <message>
        <source>Only understood by the ROS 2 mqtt_client.</source>
        <translation>Versteht nur der ROS-2-mqtt_client.</translation>
    </message>
    <message>
        <source>Benchmarking suite extension; mqtt_client ignores it.</source>
        <translation>Erweiterung der Benchmarking-Suite; mqtt_client ignoriert sie.</translation>
    </message>
    <message>
        <source>Choose a file</source>
        <translation>Datei wählen</translation>
    </message>
    <message>
        <source>Choose %1</source>
        <translation>%1 wählen</translation>
    </message>
    <message>
        <source>not set</source>
        <translation>nicht gesetzt</translation>
    </message>
    <message>
        <source>(mixed)</source>
        <translation>(gemischt)</translation>
    </message>
    <message>
        <source>default (%1)</source>
        <translation>Vorgabe (%1)</translation>
    </message>
    <message>
        <source>default: %1</source>
        <translation>Vorgabe: %1</translation>
    </message>
</context>
<context>
    <name>OptionSchema</name>
    <message>
        <source>IP address or hostname of the MQTT broker</source>
        <translation>IP-Adresse oder Hostname des MQTT-Brokers</translation>
    </message>
    <message>
        <source>port the broker listens on</source>
        <translation>Port, auf dem der Broker lauscht</translation>
    </message>
    <message>
        <source>user name for the broker (anonymous if empty)</source>
        <translation>Benutzername für den Broker (anonym, wenn leer)</translation>
    </message>
    <message>
        <source>password for the broker</source>
        <translation>Passwort für den Broker</translation>
    </message>
    <message>
        <source>connect with SSL/TLS</source>
        <translation>mit SSL/TLS verbinden</translation>
    </message>
    <message>
        <source>CA certificate the client trusts (relative to ROS_HOME)</source>
        <translation>CA-Zertifikat, dem der Client vertraut (relativ zu ROS_HOME)</translation>
    </message>
    <message>
        <source>unique client ID (the broker may generate one if empty)</source>
        <translation>eindeutige Client-ID (wenn leer, vergibt der Broker eine)</translation>
    </message>
    <message>
        <source>messages buffered while disconnected (needs a client ID)</source>
        <translation>gepufferte Nachrichten ohne Verbindung (braucht eine Client-ID)</translation>
    </message>
    <message>
        <source>directory for buffered messages (relative to ROS_HOME)</source>
        <translation>Verzeichnis für gepufferte Nachrichten (relativ zu ROS_HOME)</translation>
    </message>
    <message>
        <source>buffer messages while disconnected</source>
        <translation>Nachrichten ohne Verbindung puffern</translation>
    </message>
    <message>
        <source>topic of the last-will message (none if empty)</source>
        <translation>Topic der Last-Will-Nachricht (keine, wenn leer)</translation>
    </message>
    <message>
        <source>last-will message</source>
        <translation>Last-Will-Nachricht</translation>
    </message>
    <message>
        <source>QoS of the last-will message</source>
        <translation>QoS der Last-Will-Nachricht</translation>
    </message>
    <message>
        <source>retain the last-will message</source>
        <translation>Last-Will-Nachricht behalten (retained)</translation>
    </message>
    <message>
        <source>start a clean session on every connect</source>
        <translation>bei jeder Verbindung eine frische Sitzung beginnen</translation>
    </message>
    <message>
        <source>keep-alive interval in seconds</source>
        <translation>Keep-Alive-Intervall in Sekunden</translation>
    </message>
    <message>
        <source>maximum number of messages in flight</source>
        <translation>höchste Zahl unbestätigter Nachrichten</translation>
    </message>
    <message>
        <source>client certificate (relative to ROS_HOME)</source>
        <translation>Client-Zertifikat (relativ zu ROS_HOME)</translation>
    </message>
    <message>
        <source>client private key (relative to ROS_HOME)</source>
        <translation>privater Schlüssel des Clients (relativ zu ROS_HOME)</translation>
    </message>
    <message>
        <source>password of the client private key</source>
        <translation>Passwort des privaten Client-Schlüssels</translation>
    </message>
    <message>
        <source>TLS version as Paho&apos;s ssl_options value (3 = TLS 1.2)</source>
        <translation>TLS-Version als Wert von Pahos ssl_options (3 = TLS 1.2)</translation>
    </message>
    <message>
        <source>verify the broker&apos;s certificate</source>
        <translation>Zertifikat des Brokers prüfen</translation>
    </message>
    <message>
        <source>ALPN protocols to negotiate (e.g. x-amzn-mqtt-ca)</source>
        <translation>auszuhandelnde ALPN-Protokolle (z. B. x-amzn-mqtt-ca)</translation>
    </message>
    <message>
        <source>ROS topic to subscribe to</source>
        <translation>zu abonnierendes ROS-Topic</translation>
    </message>
    <message>
        <source>ROS topic to publish on</source>
        <translation>ROS-Topic, auf dem veröffentlicht wird</translation>
    </message>
    <message>
        <source>MQTT topic to publish on</source>
        <translation>MQTT-Topic, auf dem veröffentlicht wird</translation>
    </message>
    <message>
        <source>MQTT topic to subscribe to</source>
        <translation>zu abonnierendes MQTT-Topic</translation>
    </message>
    <message>
        <source>send std_msgs primitives as plain text</source>
        <translation>std_msgs-Primitivwerte als reinen Text senden</translation>
    </message>
    <message>
        <source>send messages as JSON (needs ros_type)</source>
        <translation>Nachrichten als JSON senden (braucht ros_type)</translation>
    </message>
    <message>
        <source>fixed ROS message type, e.g. std_msgs/msg/Bool</source>
        <translation>fester ROS-Nachrichtentyp, z. B. std_msgs/msg/Bool</translation>
    </message>
    <message>
        <source>prepend a send time stamp for latency measurement</source>
        <translation>einen Sende-Zeitstempel zur Latenzmessung voranstellen</translation>
    </message>
    <message>
        <source>ROS subscriber queue size</source>
        <translation>Warteschlangenlänge des ROS-Subscribers</translation>
    </message>
    <message>
        <source>ROS publisher queue size</source>
        <translation>Warteschlangenlänge des ROS-Publishers</translation>
    </message>
    <message>
        <source>latch the ROS publisher</source>
        <translation>ROS-Publisher als latched anlegen</translation>
    </message>
    <message>
        <source>ROS 2 QoS reliability</source>
        <translation>ROS-2-QoS Zuverlässigkeit</translation>
    </message>
    <message>
        <source>ROS 2 QoS durability</source>
        <translation>ROS-2-QoS Dauerhaftigkeit</translation>
    </message>
    <message>
        <source>MQTT QoS (0, 1 or 2)</source>
        <translation>MQTT-QoS (0, 1 oder 2)</translation>
    </message>
    <message>
        <source>publish retained on MQTT</source>
        <translation>auf MQTT als retained veröffentlichen</translation>
    </message>
    <message>
        <source>benchmarking suite: publish in/out time stamps under this prefix</source>
        <translation>Benchmarking-Suite: Ein-/Ausgangs-Zeitstempel unter diesem Präfix veröffentlichen</translation>
    </message>
    <message>
        <source>verify the broker&apos;s certificate (mqtt_client 2.4.1)</source>
        <translation>das Zertifikat des Brokers prüfen (mqtt_client 2.4.1)</translation>
    </message>
</context>
<context>
    <name>PayloadText</name>
    <message>
        <source>%1; not JSON: %2 at byte %3</source>
        <translation>%1; kein JSON: %2 bei Byte %3</translation>
    </message>
    <message>
        <source>%1; showing the first %2</source>
        <translation>%1; gezeigt werden die ersten %2</translation>
    </message>
    <message>
        <source>%1; too large to show as JSON, showing the first %2 as text</source>
        <translation>%1; zu groß für die JSON-Ansicht, die ersten %2 werden als Text gezeigt</translation>
    </message>
    <message>
        <source>%1; indented view cut at %2 characters</source>
        <translation>%1; eingerückte Ansicht nach %2 Zeichen abgeschnitten</translation>
    </message>
</context>
<context>
    <name>PeerConfig</name>
    <message>
        <source>client.last_will.topic &apos;%1&apos; is kept; both ends would announce their death on the same topic.</source>
        <translation>client.last_will.topic &apos;%1&apos; bleibt; beide Enden melden ihren Ausfall dann auf demselben Topic.</translation>
    </message>
    <message>
        <source>ros2mqtt &apos;%1&apos; publishes on &apos;%2&apos;, which has a wildcard; it has no peer mapping.</source>
        <translation>ros2mqtt &apos;%1&apos; veröffentlicht auf &apos;%2&apos;, das einen Platzhalter enthält; es bekommt keine Gegen-Zuordnung.</translation>
    </message>
    <message>
        <source>mqtt2ros &apos;%1&apos; is a wildcard subscription; the peer cannot publish on it, so it has no peer mapping.</source>
        <translation>mqtt2ros &apos;%1&apos; ist ein Platzhalter-Abo; die Gegenstelle kann darauf nicht veröffentlichen, daher keine Gegen-Zuordnung.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is stamped: the peer publishes its latency on ~/latencies%2.</source>
        <translation>&apos;%1&apos; trägt Zeitstempel: Die Gegenstelle veröffentlicht die Latenz auf ~/latencies%2.</translation>
    </message>
    <message>
        <source>timestamp_topic_prefix of &apos;%1&apos; names this host&apos;s stamps; set the peer&apos;s own prefix by hand.</source>
        <translation>timestamp_topic_prefix von &apos;%1&apos; benennt die Zeitstempel dieses Rechners; das eigene Präfix der Gegenstelle von Hand setzen.</translation>
    </message>
</context>
<context>
    <name>Pipeline</name>
    <message>
        <source>a pipeline is a mapping with topics_in_order</source>
        <translation>eine Pipeline ist eine Zuordnung mit topics_in_order</translation>
    </message>
    <message>
        <source>topics_in_order is missing or not a list</source>
        <translation>topics_in_order fehlt oder ist keine Liste</translation>
    </message>
    <message>
        <source>topics_in_order is empty</source>
        <translation>topics_in_order ist leer</translation>
    </message>
    <message>
        <source>every entry of topics_in_order must be a topic name</source>
        <translation>jeder Eintrag von topics_in_order muss ein Topic-Name sein</translation>
    </message>
    <message>
        <source>a topic starts with a byte-order mark (U+FEFF)</source>
        <translation>ein Topic beginnt mit einer Bytereihenfolge-Markierung (U+FEFF)</translation>
    </message>
    <message>
        <source>the topic %1 holds the control character U+%2 at %3</source>
        <translation>das Topic %1 enthält das Steuerzeichen U+%2 an Stelle %3</translation>
    </message>
    <message>
        <source>metrics_window must be a whole number of samples (0: whole run)</source>
        <translation>metrics_window muss eine ganze Zahl von Proben sein (0: ganzer Lauf)</translation>
    </message>
    <message>
        <source>one_clock is true or false</source>
        <translation>one_clock ist true oder false</translation>
    </message>
    <message>
        <source>hosts must map topics to host names</source>
        <translation>hosts muss Topics Rechnernamen zuordnen</translation>
    </message>
    <message>
        <source>the host of %1 must be a name</source>
        <translation>der Rechner von %1 muss ein Name sein</translation>
    </message>
    <message>
        <source>hosts names %1, which is not in topics_in_order</source>
        <translation>hosts nennt %1, das nicht in topics_in_order steht</translation>
    </message>
    <message>
        <source>the host of %1 holds a control character</source>
        <translation>der Host von %1 enthält ein Steuerzeichen</translation>
    </message>
</context>
<context>
    <name>PipelineLabels</name>
    <message>
        <source>%1 → %2</source>
        <translation>%1 → %2</translation>
    </message>
    <message>
        <source>%1 (%2 → %3)</source>
        <translation>%1 (%2 → %3)</translation>
    </message>
</context>
<context>
    <name>PipelineModel</name>
    <message>
        <source>The machine whose clock stamps this topic; stages between different hosts are crossings.</source>
        <translation>Der Rechner, dessen Uhr dieses Topic stempelt; Stufen zwischen verschiedenen Rechnern sind Übergänge.</translation>
    </message>
    <message>
        <source>%1
The stage from the previous stamp crosses from %2 to %3.</source>
        <translation>%1
Die Stufe vom vorigen Zeitstempel geht von %2 zu %3.</translation>
    </message>
    <message>
        <source>#</source>
        <translation>#</translation>
    </message>
    <message>
        <source>Stamp topic</source>
        <translation>Zeitstempel-Topic</translation>
    </message>
    <message>
        <source>Host</source>
        <translation>Rechner</translation>
    </message>
    <message>
        <source>Stamps</source>
        <translation>Zeitstempel</translation>
    </message>
</context>
<context>
    <name>PipelineSeries</name>
    <message>
        <source>total</source>
        <translation>gesamt</translation>
    </message>
    <message>
        <source>communication, round trip</source>
        <translation>Kommunikation, hin und zurück</translation>
    </message>
    <message>
        <source>communication, one way (half the round trip)</source>
        <translation>Kommunikation, eine Richtung (halbe Umlaufzeit)</translation>
    </message>
    <message>
        <source>communication, there (%1 → %2)</source>
        <translation>Kommunikation, hin (%1 → %2)</translation>
    </message>
    <message>
        <source>communication, back (%1 → %2)</source>
        <translation>Kommunikation, zurück (%1 → %2)</translation>
    </message>
    <message>
        <source>clock offset (%1 ahead of %2)</source>
        <translation>Uhrenversatz (%1 vor %2)</translation>
    </message>
    <message>
        <source>%1, clocks measured</source>
        <translation>%1, Uhren gemessen</translation>
    </message>
    <message>
        <source>communication, %1 → %2, clocks measured</source>
        <translation>Kommunikation, %1 → %2, Uhren gemessen</translation>
    </message>
    <message>
        <source>path asymmetry (there − half the round trip)</source>
        <translation>Wegasymmetrie (hin − halbe Umlaufzeit)</translation>
    </message>
</context>
<context>
    <name>PlanHosts</name>
    <message>
        <source>program is the absolute path of bridgescope on the far host (/usr/bin/bridgescope), at most %1 characters</source>
        <translation>program ist der absolute Pfad von bridgescope auf dem entfernten Host (/usr/bin/bridgescope), höchstens %1 Zeichen</translation>
    </message>
    <message>
        <source>a host is ssh://user@host[:port] or {url: ssh://…, program: PATH}</source>
        <translation>ein Host ist ssh://user@host[:port] oder {url: ssh://…, program: PFAD}</translation>
    </message>
    <message>
        <source>hosts is {vehicle: ssh://user@host, cloud: ssh://user@host}</source>
        <translation>hosts ist {vehicle: ssh://user@host, cloud: ssh://user@host}</translation>
    </message>
    <message>
        <source>unknown host &apos;%1&apos;: a plan&apos;s hosts are vehicle and cloud</source>
        <translation>unbekannter Host &apos;%1&apos;: die Hosts eines Plans sind vehicle und cloud</translation>
    </message>
    <message>
        <source>program is bridgescope&apos;s path on the hosts: it needs hosts:</source>
        <translation>program ist der Pfad von bridgescope auf den Hosts: es braucht hosts:</translation>
    </message>
</context>
<context>
    <name>ProbeCommand</name>
    <message>
        <source>sent</source>
        <translation>gesendet</translation>
    </message>
    <message>
        <source>received</source>
        <translation>empfangen</translation>
    </message>
    <message>
        <source>lost</source>
        <translation>verloren</translation>
    </message>
    <message>
        <source>%1 (%2 %)</source>
        <translation>%1 (%2 %)</translation>
    </message>
    <message>
        <source>out of order</source>
        <translation>außer der Reihe</translation>
    </message>
    <message>
        <source>duplicates</source>
        <translation>Duplikate</translation>
    </message>
    <message>
        <source>send rate</source>
        <translation>Senderate</translation>
    </message>
    <message>
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
    <message>
        <source>Round trip (ms)</source>
        <translation>Umlaufzeit (ms)</translation>
    </message>
    <message>
        <source>mean</source>
        <translation>Mittel</translation>
    </message>
    <message>
        <source>median</source>
        <translation>Median</translation>
    </message>
    <message>
        <source>std</source>
        <translation>Std.-Abw.</translation>
    </message>
    <message>
        <source>min</source>
        <translation>Min.</translation>
    </message>
    <message>
        <source>max</source>
        <translation>Max.</translation>
    </message>
    <message>
        <source>count</source>
        <translation>Anzahl</translation>
    </message>
    <message>
        <source>rate Hz</source>
        <translation>Soll Hz</translation>
    </message>
    <message>
        <source>sent Hz</source>
        <translation>Ist Hz</translation>
    </message>
    <message>
        <source>back</source>
        <translation>zurück</translation>
    </message>
    <message>
        <source>lost %</source>
        <translation>Verl. %</translation>
    </message>
    <message>
        <source>median ms</source>
        <translation>Median ms</translation>
    </message>
    <message>
        <source>p99 ms</source>
        <translation>p99 ms</translation>
    </message>
    <message>
        <source>MB/s</source>
        <translation>MB/s</translation>
    </message>
    <message>
        <source>via an echo client on %1</source>
        <translation>über einen Echo-Client auf %1</translation>
    </message>
    <message>
        <source>back on %1</source>
        <translation>zurück auf %1</translation>
    </message>
    <message>
        <source>Link probe of %1: %2 B, QoS %3, %4 Hz, %5</source>
        <translation>Streckentest zu %1: %2 B, QoS %3, %4 Hz, %5</translation>
    </message>
    <message>
        <source>Link sweep of %1: %2 B, QoS %3, %4</source>
        <translation>Strecken-Sweep zu %1: %2 B, QoS %3, %4</translation>
    </message>
    <message>
        <source>Highest sustainable rate: %1 Hz, %2 MB/s (stopped: %3)</source>
        <translation>Höchste stabile Rate: %1 Hz, %2 MB/s (beendet: %3)</translation>
    </message>
    <message>
        <source>No sustainable rate (stopped: %1)</source>
        <translation>Keine stabile Rate (beendet: %1)</translation>
    </message>
    <message>
        <source>At that rate:</source>
        <translation>Bei dieser Rate:</translation>
    </message>
    <message>
        <source>Broker URL (default tcp://localhost:1883).</source>
        <translation>Broker-URL (Vorgabe tcp://localhost:1883).</translation>
    </message>
    <message>
        <source>Payload size in bytes, at least 24 (default 1024).</source>
        <translation>Nutzdatengröße in Bytes, mindestens 24 (Vorgabe 1024).</translation>
    </message>
    <message>
        <source>Messages per second (default 10); the first rate of a sweep.</source>
        <translation>Nachrichten je Sekunde (Vorgabe 10); die erste Rate eines Sweeps.</translation>
    </message>
    <message>
        <source>QoS of the probe messages: 0, 1 or 2 (default 0).</source>
        <translation>QoS der Testnachrichten: 0, 1 oder 2 (Vorgabe 0).</translation>
    </message>
    <message>
        <source>Messages to send (default 100).</source>
        <translation>Zu sendende Nachrichten (Vorgabe 100).</translation>
    </message>
    <message>
        <source>Seconds to wait for stragglers after the last send (default 2).</source>
        <translation>Sekunden, die nach dem letzten Senden auf Nachzügler gewartet wird (Vorgabe 2).</translation>
    </message>
    <message>
        <source>Raise the rate by 1.5x per step (about a second each) until more than 1 % is lost, the median round trip exceeds 10x the first step&apos;s (at least 10 ms) or 1 s, or the sender falls behind; report the highest sustainable rate and its throughput.</source>
        <translation>Die Rate je Schritt (jeweils etwa eine Sekunde) um das 1,5-Fache erhöhen, bis mehr als 1 % verloren geht, der Median der Umlaufzeit das Zehnfache des ersten Schritts (mindestens 10 ms) oder 1 s übersteigt oder der Sender nicht mehr nachkommt; die höchste stabile Rate und ihren Durchsatz melden.</translation>
    </message>
    <message>
        <source>Sweep: the highest rate to try (default 5000).</source>
        <translation>Sweep: höchste zu testende Rate (Vorgabe 5000).</translation>
    </message>
    <message>
        <source>Print one JSON document.</source>
        <translation>Ein JSON-Dokument ausgeben.</translation>
    </message>
    <message>
        <source>Echo client: send every payload from bridgescope/probe/+/ping back unchanged on .../pong, until Ctrl+C.</source>
        <translation>Echo-Client: jede Nutzlast von bridgescope/probe/+/ping unverändert auf .../pong zurücksenden, bis Strg+C.</translation>
    </message>
    <message>
        <source>Listen for the echo client&apos;s copies (.../pong) instead of the broker&apos;s own.</source>
        <translation>Auf die Kopien des Echo-Clients (.../pong) hören statt auf die des Brokers.</translation>
    </message>
    <message>
        <source>Measures the link to a broker: publishes numbered, timed messages and times their round trip, back from the broker itself or through an echo client (probe --echo) elsewhere. Reports sent, received, lost, out of order, duplicates and the round trip statistics.
Exit status: 0 measured, 1 the broker is unreachable or nothing came back, 2 bad options.</source>
        <translation>Misst die Strecke zu einem Broker: veröffentlicht nummerierte Nachrichten mit Sendezeit und misst ihre Umlaufzeit, zurück vom Broker selbst oder über einen Echo-Client (probe --echo) an anderer Stelle. Meldet gesendete, empfangene, verlorene, vertauschte und doppelte Nachrichten sowie die Statistik der Umlaufzeit.
Exit-Status: 0 gemessen, 1 Broker nicht erreichbar oder nichts kam zurück, 2 falsche Optionen.</translation>
    </message>
    <message>
        <source>probe takes no arguments, only options; see bridgescope probe --help</source>
        <translation>probe erwartet keine Argumente, nur Optionen; siehe bridgescope probe --help</translation>
    </message>
    <message>
        <source>--size takes a number of bytes</source>
        <translation>--size erwartet eine Anzahl Bytes</translation>
    </message>
    <message>
        <source>--qos must be 0, 1 or 2</source>
        <translation>--qos muss 0, 1 oder 2 sein</translation>
    </message>
    <message>
        <source>--count takes a number of messages</source>
        <translation>--count erwartet eine Anzahl Nachrichten</translation>
    </message>
    <message>
        <source>--rate, --max-rate, --max-seconds and --wait take numbers</source>
        <translation>--rate, --max-rate, --max-seconds und --wait erwarten Zahlen</translation>
    </message>
    <message>
        <source>--echo answers other probes; it cannot be combined with --sweep or --via-echo</source>
        <translation>--echo beantwortet andere Streckentests; es lässt sich nicht mit --sweep oder --via-echo kombinieren</translation>
    </message>
    <message>
        <source>Echoing %1 back on .../pong at %2 as %3; Ctrl+C to stop.</source>
        <translation>Sende %1 auf .../pong zurück, über %2 als %3; Strg+C beendet.</translation>
    </message>
    <message>
        <source>Sweeping %1 B messages from %2 Hz up to %3 Hz at %4 (at most %5 s)</source>
        <translation>Sweep mit Nachrichten zu %1 B von %2 Hz bis %3 Hz über %4 (höchstens %5 s)</translation>
    </message>
    <message>
        <source>%1 Hz: %2 of %3 back, median %4 ms, p99 %5 ms</source>
        <translation>%1 Hz: %2 von %3 zurück, Median %4 ms, p99 %5 ms</translation>
    </message>
    <message>
        <source>%1 messages echoed</source>
        <translation>%1 Nachrichten zurückgesendet</translation>
    </message>
    <message>
        <source>Nothing came back from %1.</source>
        <translation>Von %1 kam nichts zurück.</translation>
    </message>
    <message>
        <source>Sweep: stop after S seconds (default 30).</source>
        <translation>Sweep: nach S Sekunden beenden (Vorgabe 30).</translation>
    </message>
    <message>
        <source>Nothing came back through %1; is &apos;bridgescope probe --echo&apos; running on a host connected to it?</source>
        <translation>Über %1 kam nichts zurück; läuft &apos;bridgescope probe --echo&apos; auf einem Rechner, der mit diesem Broker verbunden ist?</translation>
    </message>
</context>
<context>
    <name>ProbeDialog</name>
    <message>
        <source>S&amp;weep the rate up to the link&apos;s limit</source>
        <translation>S&amp;weep: Rate bis zur Grenze der Strecke steigern</translation>
    </message>
    <message>
        <source>Back &amp;via an echo client</source>
        <translation>Rückweg über einen &amp;Echo-Client</translation>
    </message>
    <message>
        <source>&amp;Start</source>
        <translation>S&amp;tarten</translation>
    </message>
    <message>
        <source>S&amp;top</source>
        <translation>&amp;Anhalten</translation>
    </message>
    <message>
        <source>Sweep</source>
        <translation>Sweep</translation>
    </message>
    <message>
        <source>Link Probe</source>
        <translation>Streckentest</translation>
    </message>
    <message>
        <source>tcp://, ssl://, mqtt://, mqtts://, ws:// or wss://, with the port</source>
        <translation>tcp://, ssl://, mqtt://, mqtts://, ws:// oder wss://, mit Port</translation>
    </message>
    <message>
        <source> B</source>
        <translation> B</translation>
    </message>
    <message>
        <source>The whole payload, its %1-byte header included</source>
        <translation>Die gesamten Nutzdaten, einschließlich des %1-Byte-Kopfs</translation>
    </message>
    <message>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <source>The rate of a plain run; the first step of a sweep</source>
        <translation>Die Rate eines einfachen Tests; der erste Schritt eines Sweeps</translation>
    </message>
    <message>
        <source>0: at most once</source>
        <translation>0: höchstens einmal</translation>
    </message>
    <message>
        <source>1: at least once</source>
        <translation>1: mindestens einmal</translation>
    </message>
    <message>
        <source>2: exactly once</source>
        <translation>2: genau einmal</translation>
    </message>
    <message>
        <source>QoS 1 and 2 round trips include TCP&apos;s delayed acknowledgements</source>
        <translation>Umlaufzeiten mit QoS 1 und 2 enthalten die verzögerten Bestätigungen von TCP</translation>
    </message>
    <message>
        <source> messages</source>
        <translation> Nachrichten</translation>
    </message>
    <message>
        <source>Raises the rate by 1.5x per step (about a second each) until more than 1 % is lost, the round trip grows tenfold or the sender falls behind</source>
        <translation>Erhöht die Rate je Schritt (jeweils etwa eine Sekunde) um das 1,5-Fache, bis mehr als 1 % verloren geht, die Umlaufzeit sich verzehnfacht oder der Sender nicht mehr nachkommt</translation>
    </message>
    <message>
        <source>Listen on …/pong for the copies of `bridgescope probe --echo` running on the other host, instead of on …/ping for the broker&apos;s own</source>
        <translation>Auf …/pong die Kopien von `bridgescope probe --echo` auf dem anderen Rechner empfangen statt auf …/ping die des Brokers</translation>
    </message>
    <message>
        <source>&amp;Broker:</source>
        <translation>&amp;Broker:</translation>
    </message>
    <message>
        <source>Payload si&amp;ze:</source>
        <translation>Nutzdaten&amp;größe:</translation>
    </message>
    <message>
        <source>&amp;Rate:</source>
        <translation>&amp;Rate:</translation>
    </message>
    <message>
        <source>&amp;QoS:</source>
        <translation>&amp;QoS:</translation>
    </message>
    <message>
        <source>Cou&amp;nt:</source>
        <translation>An&amp;zahl:</translation>
    </message>
    <message>
        <source>Round trips from this computer through the broker and back.</source>
        <translation>Umlaufzeiten von diesem Rechner über den Broker und zurück.</translation>
    </message>
    <message>
        <source>Rate Hz</source>
        <translation>Rate Hz</translation>
    </message>
    <message>
        <source>Sent Hz</source>
        <translation>Gesendet Hz</translation>
    </message>
    <message>
        <source>Median ms</source>
        <translation>Median ms</translation>
    </message>
    <message>
        <source>Lost %</source>
        <translation>Verloren %</translation>
    </message>
    <message>
        <source>Sent</source>
        <translation>Gesendet</translation>
    </message>
    <message>
        <source>Received</source>
        <translation>Empfangen</translation>
    </message>
    <message>
        <source>Lost</source>
        <translation>Verloren</translation>
    </message>
    <message>
        <source>Out of order</source>
        <translation>Außer der Reihe</translation>
    </message>
    <message>
        <source>Mean</source>
        <translation>Mittel</translation>
    </message>
    <message>
        <source>Median</source>
        <translation>Median</translation>
    </message>
    <message>
        <source>Std</source>
        <translation>Std.-Abw.</translation>
    </message>
    <message>
        <source>Min</source>
        <translation>Min.</translation>
    </message>
    <message>
        <source>Max</source>
        <translation>Max.</translation>
    </message>
    <message>
        <source>Connected as %1; sending on %2.</source>
        <translation>Verbunden als %1; sende auf %2.</translation>
    </message>
    <message>
        <source>Connecting to %1…</source>
        <translation>Verbinde mit %1 …</translation>
    </message>
    <message>
        <source>Stopping…</source>
        <translation>Wird angehalten …</translation>
    </message>
    <message>
        <source>step %1</source>
        <translation>Schritt %1</translation>
    </message>
    <message>
        <source>Step %1: sending at %2…</source>
        <translation>Schritt %1: sende mit %2 …</translation>
    </message>
    <message>
        <source>Sending %1 messages at %2…</source>
        <translation>Sende %1 Nachrichten mit %2 …</translation>
    </message>
    <message>
        <source>%1 in flight</source>
        <translation>%1 unterwegs</translation>
    </message>
    <message>
        <source>round trip [ms]</source>
        <translation>Umlaufzeit [ms]</translation>
    </message>
    <message>
        <source>Waiting for the first round trip…</source>
        <translation>Warte auf den ersten Umlauf …</translation>
    </message>
    <message>
        <source>Start the probe to plot the ECDF of its round trips</source>
        <translation>Den Test starten, um die ECDF seiner Umlaufzeiten zu zeichnen</translation>
    </message>
    <message>
        <source>%1 (%2 %)</source>
        <translation>%1 (%2 %)</translation>
    </message>
    <message>
        <source>Highest sustainable rate: &lt;b&gt;%1&lt;/b&gt;, &lt;b&gt;%2 MB/s&lt;/b&gt;&lt;br&gt;The sweep ended: %3.</source>
        <translation>Höchste stabile Rate: &lt;b&gt;%1&lt;/b&gt;, &lt;b&gt;%2 MB/s&lt;/b&gt;&lt;br&gt;Sweep beendet: %3.</translation>
    </message>
    <message>
        <source>No sustainable rate.&lt;br&gt;The sweep ended: %1.</source>
        <translation>Keine stabile Rate.&lt;br&gt;Sweep beendet: %1.</translation>
    </message>
    <message>
        <source>Stopped by an error after %1 round trips.</source>
        <translation>Nach %1 Umläufen durch einen Fehler gestoppt.</translation>
    </message>
    <message>
        <source>The probe could not run.</source>
        <translation>Der Test ließ sich nicht ausführen.</translation>
    </message>
    <message numerus="yes">
        <source>Sweep stopped after %n step(s).</source>
        <translation>
            <numerusform>Sweep nach %n Schritt angehalten.</numerusform>
            <numerusform>Sweep nach %n Schritten angehalten.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Sweep done: %n step(s).</source>
        <translation>
            <numerusform>Sweep fertig: %n Schritt.</numerusform>
            <numerusform>Sweep fertig: %n Schritte.</numerusform>
        </translation>
    </message>
    <message>
        <source>Stopped: %1 of %2 messages came back.</source>
        <translation>Angehalten: %1 von %2 Nachrichten kamen zurück.</translation>
    </message>
    <message>
        <source>Done: %1 of %2 messages came back.</source>
        <translation>Fertig: %1 von %2 Nachrichten kamen zurück.</translation>
    </message>
    <message>
        <source>The highest sustainable rate</source>
        <translation>Die höchste stabile Rate</translation>
    </message>
    <message>
        <source>Messages</source>
        <translation>Nachrichten</translation>
    </message>
    <message>
        <source>Messages at %1</source>
        <translation>Nachrichten bei %1</translation>
    </message>
    <message>
        <source>Round trip [ms]</source>
        <translation>Umlaufzeit [ms]</translation>
    </message>
    <message>
        <source>Round trip at %1 [ms]</source>
        <translation>Umlaufzeit bei %1 [ms]</translation>
    </message>
    <message>
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
</context>
<context>
    <name>ProblemModel</name>
    <message>
        <source>1 error</source>
        <translation>1 Fehler</translation>
    </message>
    <message>
        <source>%1 errors</source>
        <translation>%1 Fehler</translation>
    </message>
    <message>
        <source>1 warning</source>
        <translation>1 Warnung</translation>
    </message>
    <message>
        <source>%1 warnings</source>
        <translation>%1 Warnungen</translation>
    </message>
    <message>
        <source>no problems</source>
        <translation>keine Probleme</translation>
    </message>
    <message>
        <source>line %1, column %2</source>
        <translation>Zeile %1, Spalte %2</translation>
    </message>
    <message>
        <source>new mapping</source>
        <translation>neue Zuordnung</translation>
    </message>
    <message>
        <source>Problem</source>
        <translation>Problem</translation>
    </message>
    <message>
        <source>Where</source>
        <translation>Ort</translation>
    </message>
</context>
<context>
    <name>ProblemsPanel</name>
    <message>
        <source>&amp;Problems: %1</source>
        <translation>&amp;Probleme: %1</translation>
    </message>
    <message>
        <source>auto</source>
        <translation>auto</translation>
    </message>
    <message>
        <source>The mqtt_client release the config is checked against. Keys it does not read are flagged with the release that brings them; auto is the newest release that loads the layout. The choice is kept for this file.</source>
        <translation>Das mqtt_client-Release, gegen das die Konfiguration geprüft wird. Schlüssel, die es nicht liest, werden mit dem Release markiert, das sie bringt; auto ist das neueste Release, das das Layout lädt. Die Wahl bleibt für diese Datei erhalten.</translation>
    </message>
    <message>
        <source>Tar&amp;get: mqtt_client</source>
        <translation>&amp;Ziel: mqtt_client</translation>
    </message>
</context>
<context>
    <name>PrometheusAnswer</name>
    <message>
        <source>not JSON at byte %1 (%2)</source>
        <translation>kein JSON bei Byte %1 (%2)</translation>
    </message>
    <message>
        <source>not an answer of the Prometheus HTTP API (no object)</source>
        <translation>keine Antwort der Prometheus-HTTP-API (kein Objekt)</translation>
    </message>
    <message>
        <source>the server refused the query: %1: %2</source>
        <translation>der Server hat die Abfrage abgelehnt: %1: %2</translation>
    </message>
    <message>
        <source>not an answer of the Prometheus HTTP API (status &quot;%1&quot;)</source>
        <translation>keine Antwort der Prometheus-HTTP-API (Status „%1“)</translation>
    </message>
    <message>
        <source>not an answer of the Prometheus HTTP API (result type &quot;%1&quot;)</source>
        <translation>keine Antwort der Prometheus-HTTP-API (Ergebnistyp „%1“)</translation>
    </message>
</context>
<context>
    <name>PrometheusClient</name>
    <message>
        <source>not a URL: %1</source>
        <translation>keine URL: %1</translation>
    </message>
    <message>
        <source>a Prometheus server is reached over http or https, not %1</source>
        <translation>ein Prometheus-Server wird über http oder https erreicht, nicht über %1</translation>
    </message>
    <message>
        <source>the URL names no host: %1</source>
        <translation>die URL nennt keinen Rechner: %1</translation>
    </message>
    <message>
        <source>the URL must not hold a user or password: give them beside it</source>
        <translation>die URL darf keinen Benutzer und kein Passwort enthalten: diese daneben angeben</translation>
    </message>
    <message>
        <source>the URL is the server&apos;s base, without a query: %1</source>
        <translation>die URL ist die Basis des Servers, ohne Abfrage: %1</translation>
    </message>
    <message>
        <source>no Prometheus server chosen</source>
        <translation>kein Prometheus-Server gewählt</translation>
    </message>
    <message>
        <source>the server refused the credentials (HTTP %1)</source>
        <translation>der Server hat die Zugangsdaten abgelehnt (HTTP %1)</translation>
    </message>
    <message>
        <source>the answer is larger than %1 MiB: refused</source>
        <translation>die Antwort ist größer als %1 MiB: abgelehnt</translation>
    </message>
    <message>
        <source>no answer within %1 s</source>
        <translation>keine Antwort innerhalb von %1 s</translation>
    </message>
    <message>
        <source>aborted</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>the answers in flight are larger than %1 MiB together: refused</source>
        <translation>die laufenden Antworten sind zusammen größer als %1 MiB: abgelehnt</translation>
    </message>
</context>
<context>
    <name>PublishDialog</name>
    <message>
        <source>&amp;Retained</source>
        <translation>&amp;Retained</translation>
    </message>
    <message>
        <source>Publish to MQTT</source>
        <translation>An MQTT veröffentlichen</translation>
    </message>
    <message>
        <source>Text</source>
        <translation>Text</translation>
    </message>
    <message>
        <source>JSON</source>
        <translation>JSON</translation>
    </message>
    <message>
        <source>ROS message</source>
        <translation>ROS-Nachricht</translation>
    </message>
    <message>
        <source>&amp;Topic:</source>
        <translation>&amp;Topic:</translation>
    </message>
    <message>
        <source>&amp;QoS:</source>
        <translation>&amp;QoS:</translation>
    </message>
    <message>
        <source>&amp;Format:</source>
        <translation>&amp;Format:</translation>
    </message>
    <message>
        <source>P&amp;ayload:</source>
        <translation>N&amp;utzdaten:</translation>
    </message>
    <message>
        <source>&amp;Publish</source>
        <translation>&amp;Veröffentlichen</translation>
    </message>
    <message>
        <source>Publish (Ctrl+Enter)</source>
        <translation>Veröffentlichen (Strg+Eingabe)</translation>
    </message>
    <message>
        <source>ROS message (%1)</source>
        <translation>ROS-Nachricht (%1)</translation>
    </message>
    <message>
        <source>%1 as YAML or JSON, sent in ROS serialization as mqtt_client does%2. %3</source>
        <translation>%1 als YAML oder JSON, gesendet in ROS-Serialisierung wie von mqtt_client%2. %3</translation>
    </message>
    <message>
        <source>, after the send stamp</source>
        <translation>, nach dem Sendezeitstempel</translation>
    </message>
    <message>
        <source>Not sent: %1</source>
        <translation>Nicht gesendet: %1</translation>
    </message>
    <message>
        <source>Replace the retained message</source>
        <translation>Retained-Nachricht ersetzen</translation>
    </message>
    <message>
        <source>The broker keeps a retained message for %1. Replace it?</source>
        <translation>Der Broker hält eine Retained-Nachricht für %1. Ersetzen?</translation>
    </message>
    <message>
        <source>Not sent: the retained message stays.</source>
        <translation>Nicht gesendet: die Retained-Nachricht bleibt.</translation>
    </message>
    <message numerus="yes">
        <source>%1: published %n bytes to %2.</source>
        <translation>
            <numerusform>%1: %n Byte an %2 veröffentlicht.</numerusform>
            <numerusform>%1: %n Bytes an %2 veröffentlicht.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>PublishPayload</name>
    <message>
        <source>not JSON: %1 at character %2</source>
        <translation>kein JSON: %1 bei Zeichen %2</translation>
    </message>
    <message>
        <source>no ROS type is announced for this topic</source>
        <translation>für dieses Topic ist kein ROS-Typ angekündigt</translation>
    </message>
    <message>
        <source>not YAML or JSON: %1</source>
        <translation>kein YAML oder JSON: %1</translation>
    </message>
    <message>
        <source>not a %1: %2</source>
        <translation>kein %1: %2</translation>
    </message>
    <message>
        <source>Values of the last message.</source>
        <translation>Werte der letzten Nachricht.</translation>
    </message>
    <message>
        <source>the last message is too large to edit here</source>
        <translation>die letzte Nachricht ist zu groß, um sie hier zu bearbeiten</translation>
    </message>
    <message>
        <source>no message yet</source>
        <translation>noch keine Nachricht</translation>
    </message>
    <message>
        <source>Zero values (%1).</source>
        <translation>Nullwerte (%1).</translation>
    </message>
</context>
<context>
    <name>RateChart</name>
    <message>
        <source>seconds ago</source>
        <translation>vor Sekunden</translation>
    </message>
</context>
<context>
    <name>RecordCommand</name>
    <message>
        <source>Pipeline YAML (the suite&apos;s metrics-logger file).</source>
        <translation>Pipeline-YAML (die Metrics-Logger-Datei der Suite).</translation>
    </message>
    <message>
        <source>Broker URL (default tcp://localhost:1883).</source>
        <translation>Broker-URL (Vorgabe tcp://localhost:1883).</translation>
    </message>
    <message>
        <source>ROS master URI (default $ROS_MASTER_URI).</source>
        <translation>ROS-Master-URI (Vorgabe $ROS_MASTER_URI).</translation>
    </message>
    <message>
        <source>Stop after N complete samples.</source>
        <translation>Nach N vollständigen Proben beenden.</translation>
    </message>
    <message>
        <source>Stop after S seconds.</source>
        <translation>Nach S Sekunden beenden.</translation>
    </message>
    <message>
        <source>The run file to write (never overwritten).</source>
        <translation>Die zu schreibende Laufdatei (wird nie überschrieben).</translation>
    </message>
    <message>
        <source>Name of the run (default: the file&apos;s name).</source>
        <translation>Name des Laufs (Vorgabe: der Dateiname).</translation>
    </message>
    <message>
        <source>Notes to keep with the run.</source>
        <translation>Notizen, die mit dem Lauf gespeichert werden.</translation>
    </message>
    <message>
        <source>The bridge config in use, kept with the run.</source>
        <translation>Die verwendete Bridge-Konfiguration; wird mit dem Lauf gespeichert.</translation>
    </message>
    <message>
        <source>record needs --pipeline and -o; see bridgescope record --help</source>
        <translation>record braucht --pipeline und -o; siehe bridgescope record --help</translation>
    </message>
    <message>
        <source>--samples takes a number of samples</source>
        <translation>--samples erwartet eine Anzahl Proben</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1 exists already; a run is never overwritten</source>
        <translation>%1 existiert bereits; ein Lauf wird nie überschrieben</translation>
    </message>
    <message>
        <source>recording failed: %1</source>
        <translation>Aufzeichnung fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>%1 s: %2 stamps committed, %3 complete samples, %4 dropped, %5 waiting</source>
        <translation>%1 s: %2 Zeitstempel festgeschrieben, %3 vollständige Proben, %4 verworfen, %5 wartend</translation>
    </message>
    <message>
        <source>%1: %2 complete samples, %3 stamps</source>
        <translation>%1: %2 vollständige Proben, %3 Zeitstempel</translation>
    </message>
    <message>
        <source>%1 is not YAML: the run keeps no copy of it (its credentials could not be found)</source>
        <translation>%1 ist kein YAML: der Lauf behält keine Kopie davon (seine Zugangsdaten ließen sich nicht finden)</translation>
    </message>
    <message>
        <source>Exit 0 even when no stamp was recorded (an empty run on purpose).</source>
        <translation>Status 0 auch dann, wenn kein Zeitstempel aufgezeichnet wurde (ein absichtlich leerer Lauf).</translation>
    </message>
    <message>
        <source>nothing was recorded (%1); --allow-empty accepts an empty run</source>
        <translation>nichts wurde aufgezeichnet (%1); --allow-empty lässt einen leeren Lauf zu</translation>
    </message>
    <message>
        <source>no stamp of the pipeline&apos;s topics arrived</source>
        <translation>kein Zeitstempel der Pipeline-Topics kam an</translation>
    </message>
    <message>
        <source>Every stamp comes from one clock (one machine): each direction&apos;s own one-way latency, no clock offset (kept with the run).</source>
        <translation>Jeder Zeitstempel kommt von einer Uhr (ein Rechner): die Einweg-Latenz jeder Richtung, kein Uhrenversatz (wird mit dem Lauf gespeichert).</translation>
    </message>
    <message>
        <source>stamp</source>
        <translation>Zeitstempel</translation>
    </message>
    <message>
        <source>Records a measurement run: every stamp of the pipeline from ROS 1, ROS 2 (--ros 2 or both) and MQTT, committed to the run file at least every 200 ms, until N samples are complete, S seconds passed, or Ctrl+C. A broker or master that cannot be reached, or no stamp at all, is said within 5 s; it keeps trying.
Exit status: 0 recorded, 1 nothing recorded (without --allow-empty) or the run file could not be written, 2 bad options.</source>
        <translation>Zeichnet einen Messlauf auf: jeden Zeitstempel der Pipeline von ROS 1, ROS 2 (--ros 2 oder both) und MQTT, mindestens alle 200 ms in die Laufdatei festgeschrieben, bis N Proben vollständig oder S Sekunden vergangen sind oder Strg+C gedrückt wird. Ein nicht erreichbarer Broker oder Master, oder gar kein Zeitstempel, wird innerhalb von 5 s gemeldet; es wird weiter versucht.
Exit-Status: 0 aufgezeichnet, 1 nichts aufgezeichnet (ohne --allow-empty) oder Laufdatei nicht schreibbar, 2 falsche Optionen.</translation>
    </message>
    <message>
        <source>not a measurement: %1</source>
        <translation>keine Messung: %1</translation>
    </message>
    <message>
        <source>%1 on %2</source>
        <translation>%1 auf %2</translation>
    </message>
    <message numerus="yes">
        <source>%n more topic(s)</source>
        <translation>
            <numerusform>%n weiteres Topic</numerusform>
            <numerusform>%n weitere Topics</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 malformed stamps: %2 (last: %3)</source>
        <translation>%1 fehlerhafte Zeitstempel: %2 (zuletzt: %3)</translation>
    </message>
</context>
<context>
    <name>RecordDialog</name>
    <message>
        <source>Record a Run</source>
        <translation>Lauf aufzeichnen</translation>
    </message>
    <message>
        <source>run %1</source>
        <translation>Lauf %1</translation>
    </message>
    <message>
        <source>What is special about this run: link, QoS, load, software versions…</source>
        <translation>Was diesen Lauf ausmacht: Strecke, QoS, Last, Softwareversionen …</translation>
    </message>
    <message>
        <source>&amp;Browse…</source>
        <translation>&amp;Durchsuchen …</translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation>&amp;Name:</translation>
    </message>
    <message>
        <source>N&amp;otes:</source>
        <translation>N&amp;otizen:</translation>
    </message>
    <message>
        <source>Run &amp;file:</source>
        <translation>&amp;Laufdatei:</translation>
    </message>
    <message>
        <source>&amp;Record</source>
        <translation>&amp;Aufzeichnen</translation>
    </message>
    <message>
        <source>Run File</source>
        <translation>Laufdatei</translation>
    </message>
    <message>
        <source>Bridgescope runs (*.%1)</source>
        <translation>Bridgescope-Läufe (*.%1)</translation>
    </message>
</context>
<context>
    <name>ReferenceBridge</name>
    <message>
        <source>ignored a malformed type announcement for %1: %2</source>
        <translation>fehlerhafte Typankündigung für %1 ignoriert: %2</translation>
    </message>
    <message>
        <source>MQTT %1 -&gt; ROS %2 (%3%4)</source>
        <translation>MQTT %1 -&gt; ROS %2 (%3%4)</translation>
    </message>
    <message>
        <source>, stamped</source>
        <translation>, mit Zeitstempel</translation>
    </message>
    <message>
        <source>not a bridge config: %1</source>
        <translation>keine Bridge-Konfiguration: %1</translation>
    </message>
    <message>
        <source>%1: qos must be 0, 1 or 2 (give $(arg ...) values with --arg NAME=VALUE)</source>
        <translation>%1: qos muss 0, 1 oder 2 sein (Werte für $(arg ...) mit --arg NAME=VALUE angeben)</translation>
    </message>
    <message>
        <source>a mapping without ros_topic or mqtt_topic</source>
        <translation>eine Zuordnung ohne ros_topic oder mqtt_topic</translation>
    </message>
    <message>
        <source>the config has no mapping to bridge</source>
        <translation>die Konfiguration hat keine zu übertragende Zuordnung</translation>
    </message>
    <message>
        <source>waiting for the ROS master…</source>
        <translation>warte auf den ROS-Master …</translation>
    </message>
    <message>
        <source>ROS node %1 started</source>
        <translation>ROS-Knoten %1 gestartet</translation>
    </message>
    <message>
        <source>MQTT %1 -&gt; ROS %2 (primitive)</source>
        <translation>MQTT %1 -&gt; ROS %2 (primitiv)</translation>
    </message>
    <message>
        <source>reconnected to %1</source>
        <translation>wieder mit %1 verbunden</translation>
    </message>
    <message>
        <source>lost the broker (%1); reconnecting</source>
        <translation>Broker verloren (%1); verbinde erneut</translation>
    </message>
    <message>
        <source>connecting to %1…</source>
        <translation>verbinde mit %1 …</translation>
    </message>
    <message>
        <source>connected to %1</source>
        <translation>mit %1 verbunden</translation>
    </message>
    <message>
        <source>cannot subscribe to %1: %2</source>
        <translation>%1 lässt sich nicht abonnieren: %2</translation>
    </message>
    <message>
        <source>ROS %1 -&gt; MQTT %2%3</source>
        <translation>ROS %1 -&gt; MQTT %2%3</translation>
    </message>
    <message>
        <source> (primitive)</source>
        <translation> (primitiv)</translation>
    </message>
    <message>
        <source> (stamped)</source>
        <translation> (mit Zeitstempel)</translation>
    </message>
    <message>
        <source>the config uses %1: give the values with %2</source>
        <translation>die Konfiguration verwendet %1: die Werte mit %2 angeben</translation>
    </message>
    <message>
        <source>MQTT %1 -&gt; ROS %2: the type changed to %3%4</source>
        <translation>MQTT %1 -&gt; ROS %2: der Typ ist jetzt %3%4</translation>
    </message>
    <message>
        <source> (further changes are not logged)</source>
        <translation> (weitere Wechsel werden nicht protokolliert)</translation>
    </message>
    <message>
        <source>ignored the ROS 2 type announcement for %1 (%2): this bridge speaks ROS 1</source>
        <translation>ROS-2-Typankündigung für %1 (%2) ignoriert: diese Bridge spricht ROS 1</translation>
    </message>
</context>
<context>
    <name>RegularFile</name>
    <message>
        <source>a FIFO (named pipe)</source>
        <translation>ein FIFO (eine benannte Pipe)</translation>
    </message>
    <message>
        <source>a device</source>
        <translation>ein Gerät</translation>
    </message>
    <message>
        <source>a socket</source>
        <translation>ein Socket</translation>
    </message>
    <message>
        <source>a folder</source>
        <translation>ein Ordner</translation>
    </message>
    <message>
        <source>not a regular file</source>
        <translation>keine reguläre Datei</translation>
    </message>
    <message>
        <source>%1 MiB</source>
        <translation>%1 MiB</translation>
    </message>
    <message>
        <source>%1 bytes</source>
        <translation>%1 Bytes</translation>
    </message>
    <message>
        <source>%1, not a file: refused</source>
        <translation>%1, keine Datei: abgelehnt</translation>
    </message>
    <message>
        <source>%1, more than the %2 such a file may have: refused</source>
        <translation>%1, mehr als die %2, die eine solche Datei haben darf: abgelehnt</translation>
    </message>
</context>
<context>
    <name>RemoteCommand</name>
    <message>
        <source>%1 (%2) did not finish %3 within %4 s</source>
        <translation>%1 (%2) hat %3 nicht innerhalb von %4 s beendet</translation>
    </message>
    <message>
        <source>%1 on %2 (%3) ended with status %4: %5</source>
        <translation>%1 auf %2 (%3) endete mit Status %4: %5</translation>
    </message>
</context>
<context>
    <name>RemoteHost</name>
    <message>
        <source>want ssh://user@host or ssh://user@host:port</source>
        <translation>erwartet ssh://user@host oder ssh://user@host:port</translation>
    </message>
    <message>
        <source>a host URL longer than %1 characters</source>
        <translation>eine Host-URL länger als %1 Zeichen</translation>
    </message>
    <message>
        <source>a password in a host URL is never accepted: use a key or an ssh agent (ssh://user@host)</source>
        <translation>ein Passwort in einer Host-URL wird nie angenommen: einen Schlüssel oder einen ssh-Agenten verwenden (ssh://user@host)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not an ssh:// URL: %2</source>
        <translation>&quot;%1&quot; ist keine ssh://-URL: %2</translation>
    </message>
    <message>
        <source>&quot;%1&quot; names no user: %2</source>
        <translation>&quot;%1&quot; nennt keinen Benutzer: %2</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a user name (lower-case letters, digits, &apos;_&apos; and &apos;-&apos;, at most 32, not starting with a digit or &apos;-&apos;)</source>
        <translation>&quot;%1&quot; ist kein Benutzername (Kleinbuchstaben, Ziffern, &apos;_&apos; und &apos;-&apos;, höchstens 32, nicht mit einer Ziffer oder &apos;-&apos; beginnend)</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: an IPv6 address without its closing &apos;]&apos;</source>
        <translation>&quot;%1&quot;: eine IPv6-Adresse ohne schließende &apos;]&apos;</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not an IPv6 address</source>
        <translation>&quot;%1&quot; ist keine IPv6-Adresse</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: nothing may follow the host but :port</source>
        <translation>&quot;%1&quot;: auf den Host darf nur :port folgen</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: an empty port</source>
        <translation>&quot;%1&quot;: ein leerer Port</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: an IPv6 address goes in brackets (ssh://user@[::1]:22)</source>
        <translation>&quot;%1&quot;: eine IPv6-Adresse steht in eckigen Klammern (ssh://user@[::1]:22)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; names no host: %2</source>
        <translation>&quot;%1&quot; nennt keinen Host: %2</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is neither a host name nor an IP address (a path, a query or other characters are not allowed)</source>
        <translation>&quot;%1&quot; ist weder ein Hostname noch eine IP-Adresse (ein Pfad, eine Abfrage oder andere Zeichen sind nicht erlaubt)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a port (1 to 65535)</source>
        <translation>&quot;%1&quot; ist kein Port (1 bis 65535)</translation>
    </message>
</context>
<context>
    <name>RemoteProcess</name>
    <message>
        <source>%1 (%2) already runs a program</source>
        <translation>%1 (%2) führt bereits ein Programm aus</translation>
    </message>
    <message>
        <source>ssh to %1 (%2) ended unexpectedly</source>
        <translation>ssh zu %1 (%2) endete unerwartet</translation>
    </message>
    <message>
        <source>lost %1 (%2): %3</source>
        <translation>Verbindung zu %1 (%2) verloren: %3</translation>
    </message>
    <message>
        <source>could not start the program on %1 (%2): %3</source>
        <translation>konnte das Programm auf %1 (%2) nicht starten: %3</translation>
    </message>
    <message>
        <source>the program on %1 (%2) ended with status %3: %4</source>
        <translation>das Programm auf %1 (%2) endete mit Status %3: %4</translation>
    </message>
</context>
<context>
    <name>Report</name>
    <message>
        <source>no input files</source>
        <translation>keine Eingabedateien</translation>
    </message>
    <message>
        <source>%1: no stamps of topic %2 (it has: %3)</source>
        <translation>%1: keine Zeitstempel von Topic %2 (vorhanden: %3)</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>run</source>
        <translation>Lauf</translation>
    </message>
    <message>
        <source>Latency report: %1</source>
        <translation>Latenzbericht: %1</translation>
    </message>
    <message>
        <source>Latency comparison: %1</source>
        <translation>Latenzvergleich: %1</translation>
    </message>
    <message>
        <source>total</source>
        <translation>gesamt</translation>
    </message>
    <message>
        <source>communication, one way (half the round trip)</source>
        <translation>Kommunikation, eine Richtung (halbe Umlaufzeit)</translation>
    </message>
    <message>
        <source>communication, round trip</source>
        <translation>Kommunikation, hin und zurück</translation>
    </message>
    <message>
        <source>clock offset</source>
        <translation>Uhrenversatz</translation>
    </message>
    <message>
        <source>Watch report: %1</source>
        <translation>Überwachungsbericht: %1</translation>
    </message>
    <message>
        <source>communication, there</source>
        <translation>Kommunikation, hin</translation>
    </message>
    <message>
        <source>communication, back</source>
        <translation>Kommunikation, zurück</translation>
    </message>
    <message>
        <source>path asymmetry (there − half the round trip)</source>
        <translation>Wegasymmetrie (hin − halbe Umlaufzeit)</translation>
    </message>
</context>
<context>
    <name>ReportCommand</name>
    <message>
        <source>Pipeline YAML (the suite&apos;s metrics-logger file; hosts: optional).</source>
        <translation>Pipeline-YAML (die Metrics-Logger-Datei der Suite; hosts: optional).</translation>
    </message>
    <message>
        <source>json (default), csv, md, tex, html or pdf.</source>
        <translation>json (Vorgabe), csv, md, tex, html oder pdf.</translation>
    </message>
    <message>
        <source>Statistics over the last N samples (default 0: all).</source>
        <translation>Statistik über die letzten N Proben (Vorgabe 0: alle).</translation>
    </message>
    <message>
        <source>Write to FILE instead of stdout.</source>
        <translation>In FILE statt auf die Standardausgabe schreiben.</translation>
    </message>
    <message>
        <source>Join several inputs into one run instead of comparing them.</source>
        <translation>Mehrere Eingaben zu einem Lauf zusammenführen, statt sie zu vergleichen.</translation>
    </message>
    <message>
        <source>csv: one row per sample of stage latencies in ms, not the stamps.</source>
        <translation>csv: eine Zeile je Probe mit den Stufenlatenzen in ms statt der Zeitstempel.</translation>
    </message>
    <message>
        <source>Skip CSV rows that cannot be read (each is reported) instead of failing.</source>
        <translation>CSV-Zeilen, die nicht lesbar sind, überspringen (jede wird gemeldet), statt abzubrechen.</translation>
    </message>
    <message>
        <source>Title of the report.</source>
        <translation>Titel des Berichts.</translation>
    </message>
    <message>
        <source>unknown format %1 (known: json, csv, md, tex, html, pdf)</source>
        <translation>unbekanntes Format %1 (bekannt: json, csv, md, tex, html, pdf)</translation>
    </message>
    <message>
        <source>--window takes a number of samples (0: all)</source>
        <translation>--window erwartet eine Anzahl Proben (0: alle)</translation>
    </message>
    <message>
        <source>no input files; see bridgescope report --help</source>
        <translation>keine Eingabedateien; siehe bridgescope report --help</translation>
    </message>
    <message>
        <source>reading… %1 %</source>
        <translation>lese … %1 %</translation>
    </message>
    <message>
        <source>cancelled; nothing written</source>
        <translation>abgebrochen; nichts geschrieben</translation>
    </message>
    <message>
        <source>%1 (row skipped)</source>
        <translation>%1 (Zeile übersprungen)</translation>
    </message>
    <message>
        <source>%1: no complete sample</source>
        <translation>%1: keine vollständige Probe</translation>
    </message>
    <message>
        <source>An experiment&apos;s tables: mean (default), median, std, p99, or several (mean,p99).</source>
        <translation>Die Tabellen eines Experiments: mean (Vorgabe), median, std, p99 oder mehrere (mean,p99).</translation>
    </message>
    <message>
        <source>Reports the latency statistics of measured runs: every stage, the total and, with hosts in the pipeline, the communication round trip, its one-way half and the clock offset. INPUT is a run (bridgescope record), the benchmarking suite&apos;s timestamp CSV or a ROS bag with TimeStamped topics; several inputs are compared side by side (the paper&apos;s Table I and Fig. 5), or joined into one run with --join. An experiment&apos;s folder (bridgescope experiment) gives a table per factor, its levels as columns and the stage groups as rows.
Exit status: 0 report written, 1 a run with a pipeline has no complete sample, 2 bad options or input, 130 cancelled.</source>
        <translation>Berichtet die Latenzstatistik gemessener Läufe: jede Stufe, die Gesamtlatenz und, wenn die Pipeline Rechner angibt, die Umlaufzeit der Kommunikation, deren Hälfte für eine Richtung und den Uhrenversatz. INPUT ist ein Lauf (bridgescope record), die Zeitstempel-CSV der Benchmarking-Suite oder ein ROS-Bag mit TimeStamped-Topics; mehrere Eingaben werden nebeneinander verglichen (Tabelle I und Abb. 5 des Papers) oder mit --join zu einem Lauf zusammengeführt. Der Ordner eines Experiments (bridgescope experiment) ergibt eine Tabelle je Faktor, seine Stufen als Spalten und die Stufengruppen als Zeilen.
Exit-Status: 0 Bericht geschrieben, 1 ein Lauf mit Pipeline hat keine vollständige Probe, 2 falsche Optionen oder Eingabe, 130 abgebrochen.</translation>
    </message>
    <message>
        <source>Runs, suite timestamp CSV files or bags; or an experiment&apos;s folder.</source>
        <translation>Läufe, Zeitstempel-CSV-Dateien der Suite oder Bags; oder der Ordner eines Experiments.</translation>
    </message>
    <message>
        <source>Every stamp comes from one clock (one machine): each direction&apos;s own one-way latency, no clock offset.</source>
        <translation>Jeder Zeitstempel kommt von einer Uhr (ein Rechner): die Einweg-Latenz jeder Richtung, kein Uhrenversatz.</translation>
    </message>
    <message>
        <source>%1: not a measurement: %2</source>
        <translation>%1: keine Messung: %2</translation>
    </message>
</context>
<context>
    <name>ReportFormats</name>
    <message>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
    <message>
        <source>Stage</source>
        <translation>Stufe</translation>
    </message>
    <message>
        <source>Mean [ms]</source>
        <translation>Mittel [ms]</translation>
    </message>
    <message>
        <source>Median</source>
        <translation>Median</translation>
    </message>
    <message>
        <source>Std</source>
        <translation>Std.-Abw.</translation>
    </message>
    <message>
        <source>Min</source>
        <translation>Min.</translation>
    </message>
    <message>
        <source>Max</source>
        <translation>Max.</translation>
    </message>
    <message>
        <source>p99</source>
        <translation>p99</translation>
    </message>
    <message>
        <source>Count</source>
        <translation>Anzahl</translation>
    </message>
    <message>
        <source>Mean latency [ms]</source>
        <translation>Mittlere Latenz [ms]</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Lauf</translation>
    </message>
    <message>
        <source>Samples</source>
        <translation>Proben</translation>
    </message>
    <message>
        <source>Dropped</source>
        <translation>Verworfen</translation>
    </message>
    <message>
        <source>not stopped</source>
        <translation>nicht beendet</translation>
    </message>
    <message>
        <source>%1 stamps, %2 stages</source>
        <translation>%1 Zeitstempel, %2 Stufen</translation>
    </message>
    <message>
        <source>; hosts %1; %2 crossings</source>
        <translation>; Rechner %1; %2 Übergänge</translation>
    </message>
    <message>
        <source>%1 complete, %2 dropped, %3 duplicate stamps</source>
        <translation>%1 vollständig, %2 verworfen, %3 doppelte Zeitstempel</translation>
    </message>
    <message>
        <source>the last %1 samples</source>
        <translation>die letzten %1 Proben</translation>
    </message>
    <message>
        <source>the whole run</source>
        <translation>der ganze Lauf</translation>
    </message>
    <message>
        <source>total [ms]</source>
        <translation>gesamt [ms]</translation>
    </message>
    <message>
        <source>Latency per stage</source>
        <translation>Latenz je Stufe</translation>
    </message>
    <message>
        <source>Total latency per run</source>
        <translation>Gesamtlatenz je Lauf</translation>
    </message>
    <message>
        <source>Written by Bridgescope; needs \usepackage{booktabs}.</source>
        <translation>Geschrieben von Bridgescope; benötigt \usepackage{booktabs}.</translation>
    </message>
    <message>
        <source>total</source>
        <translation>gesamt</translation>
    </message>
    <message>
        <source>communication, one way</source>
        <translation>Kommunikation, eine Richtung</translation>
    </message>
    <message>
        <source>Latency distribution</source>
        <translation>Latenzverteilung</translation>
    </message>
    <message>
        <source>ECDF</source>
        <translation>ECDF</translation>
    </message>
    <message>
        <source>Made with Bridgescope %1 on %2.</source>
        <translation>Erstellt mit Bridgescope %1 am %2.</translation>
    </message>
    <message>
        <source>Source</source>
        <translation>Quelle</translation>
    </message>
    <message>
        <source>Recorded</source>
        <translation>Aufgezeichnet</translation>
    </message>
    <message>
        <source>Pipeline</source>
        <translation>Pipeline</translation>
    </message>
    <message>
        <source>Broker</source>
        <translation>Broker</translation>
    </message>
    <message>
        <source>ROS master</source>
        <translation>ROS-Master</translation>
    </message>
    <message>
        <source>Window</source>
        <translation>Fenster</translation>
    </message>
    <message>
        <source>Host</source>
        <translation>Rechner</translation>
    </message>
    <message>
        <source>Notes</source>
        <translation>Notizen</translation>
    </message>
    <message>
        <source>a CSV file holds a single run: give one input, or join several with --join</source>
        <translation>eine CSV-Datei enthält nur einen Lauf: eine Eingabe angeben oder mehrere mit --join zusammenführen</translation>
    </message>
    <message>
        <source>Events</source>
        <translation>Ereignisse</translation>
    </message>
    <message>
        <source>%1 (%2 alerts)</source>
        <translation>%1 (%2 Alarme)</translation>
    </message>
    <message>
        <source>bridge %1</source>
        <translation>Bridge %1</translation>
    </message>
    <message>
        <source>open</source>
        <translation>offen</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Beginn</translation>
    </message>
    <message>
        <source>Duration</source>
        <translation>Dauer</translation>
    </message>
    <message>
        <source>Link</source>
        <translation>Verbindung</translation>
    </message>
    <message>
        <source>Level</source>
        <translation>Stufe</translation>
    </message>
    <message>
        <source>Why</source>
        <translation>Grund</translation>
    </message>
    <message>
        <source>%1 more events are in the JSON report.</source>
        <translation>%1 weitere Ereignisse stehen im JSON-Bericht.</translation>
    </message>
    <message>
        <source>one clock: each direction&apos;s own one-way latency, no offset</source>
        <translation>eine Uhr: die Einweg-Latenz jeder Richtung, kein Versatz</translation>
    </message>
    <message>
        <source>Clocks</source>
        <translation>Uhren</translation>
    </message>
    <message>
        <source>two clocks: offset %1 ms</source>
        <translation>zwei Uhren: Versatz %1 ms</translation>
    </message>
    <message>
        <source>two clocks: offset %1 ms %2, between %3 and %4 ms</source>
        <translation>zwei Uhren: Versatz %1 ms %2, zwischen %3 und %4 ms</translation>
    </message>
    <message>
        <source>Statistics in ms; std is the corrected standard deviation (ddof = 1). Rows in italics cross between hosts: their raw values include the clock offset. Communication: total minus every stage on one host, one way being half of it. With two clocks, a clock offset and a difference between the two legs cannot be told apart within the offset&apos;s range (neither leg takes negative time); with one clock (one_clock: true in the pipeline, or --one-clock) each direction&apos;s own one-way latency is given instead.</source>
        <translation>Statistik in ms; Std.-Abw. ist die korrigierte Standardabweichung (ddof = 1). Kursive Zeilen gehen von einem Rechner zu einem anderen: Ihre Rohwerte enthalten den Uhrenversatz. Kommunikation: gesamt minus jede Stufe, die auf einem Rechner bleibt; eine Richtung ist die Hälfte davon. Mit zwei Uhren lassen sich ein Uhrenversatz und ein Unterschied der beiden Wege innerhalb des Versatzbereichs nicht unterscheiden (kein Weg dauert negativ lange); mit einer Uhr (one_clock: true in der Pipeline oder --one-clock) wird stattdessen die Latenz jeder Richtung angegeben.</translation>
    </message>
    <message>
        <source>ROS 2</source>
        <translation>ROS 2</translation>
    </message>
    <message>
        <source>Not a measurement</source>
        <translation>Keine Messung</translation>
    </message>
    <message>
        <source>Not a measurement (%1): %2</source>
        <translation>Keine Messung (%1): %2</translation>
    </message>
    <message>
        <source>announced on the broker</source>
        <translation>am Broker angekündigt</translation>
    </message>
    <message>
        <source>%1, bridge %2</source>
        <translation>%1, Bridge %2</translation>
    </message>
    <message>
        <source>From</source>
        <translation>Von</translation>
    </message>
    <message>
        <source>Events: every change of a watched link&apos;s or bridge&apos;s state while the run was recorded, from the config and bridge named; alerts are marked.</source>
        <translation>Ereignisse: jede Zustandsänderung einer beobachteten Verbindung oder Bridge während der Aufzeichnung, aus der genannten Konfiguration und Bridge; Alarme sind markiert.</translation>
    </message>
    <message>
        <source>PDF</source>
        <translation>PDF</translation>
    </message>
    <message>
        <source>HTML (tables and SVG figure)</source>
        <translation>HTML (Tabellen und SVG-Grafik)</translation>
    </message>
    <message>
        <source>Markdown</source>
        <translation>Markdown</translation>
    </message>
    <message>
        <source>LaTeX (booktabs tabular)</source>
        <translation>LaTeX (tabular mit booktabs)</translation>
    </message>
    <message>
        <source>CSV</source>
        <translation>CSV</translation>
    </message>
    <message>
        <source>JSON</source>
        <translation>JSON</translation>
    </message>
    <message>
        <source>clocks measured: %1</source>
        <translation>Uhren gemessen: %1</translation>
    </message>
    <message>
        <source>Rows named &quot;observed&quot;: a bridge&apos;s hop latency without stamps, each message Bridgescope saw going into the bridge matched by its content with the copy it saw coming out, on Bridgescope&apos;s one clock (its own delivery included).</source>
        <translation>Zeilen namens „observed“: die Sprunglatenz einer Brücke ohne Zeitstempel, jede Nachricht, die Bridgescope in die Brücke gehen sah, nach ihrem Inhalt der Kopie zugeordnet, die es herauskommen sah, auf der einen Uhr von Bridgescope (seine eigene Zustellung eingeschlossen).</translation>
    </message>
</context>
<context>
    <name>ReportsPage</name>
    <message>
        <source>&amp;Join the inputs into one run</source>
        <translation>Eingaben zu einem Lauf zusammen&amp;führen</translation>
    </message>
    <message>
        <source>CSV: stage latencies in ms, one row per sample</source>
        <translation>CSV: Stufenlatenzen in ms, eine Zeile je Probe</translation>
    </message>
    <message>
        <source>Runs, suite timestamp CSV files and ROS bags; several are compared side by side</source>
        <translation>Läufe, Zeitstempel-CSV-Dateien der Suite und ROS-Bags; mehrere werden nebeneinander verglichen</translation>
    </message>
    <message>
        <source>whole run</source>
        <translation>ganzer Lauf</translation>
    </message>
    <message>
        <source> samples</source>
        <translation> Proben</translation>
    </message>
    <message>
        <source>from the run names</source>
        <translation>aus den Laufnamen</translation>
    </message>
    <message>
        <source>&amp;Add…</source>
        <translation>Hin&amp;zufügen …</translation>
    </message>
    <message>
        <source>&amp;Remove</source>
        <translation>&amp;Entfernen</translation>
    </message>
    <message>
        <source>&amp;Up</source>
        <translation>Nach &amp;oben</translation>
    </message>
    <message>
        <source>Do&amp;wn</source>
        <translation>Nach &amp;unten</translation>
    </message>
    <message>
        <source>&amp;Browse…</source>
        <translation>Durch&amp;suchen …</translation>
    </message>
    <message>
        <source>&amp;Export…</source>
        <translation>E&amp;xportieren …</translation>
    </message>
    <message>
        <source>Write the report to a file (Ctrl+E)</source>
        <translation>Den Bericht in eine Datei schreiben (Strg+E)</translation>
    </message>
    <message>
        <source>&amp;Format:</source>
        <translation>For&amp;mat:</translation>
    </message>
    <message>
        <source>&amp;Pipeline:</source>
        <translation>&amp;Pipeline:</translation>
    </message>
    <message>
        <source>W&amp;indow:</source>
        <translation>Fe&amp;nster:</translation>
    </message>
    <message>
        <source>&amp;Title:</source>
        <translation>&amp;Titel:</translation>
    </message>
    <message>
        <source>&amp;Inputs:</source>
        <translation>E&amp;ingaben:</translation>
    </message>
    <message>
        <source>Add runs, suite CSV files or bags to report on.</source>
        <translation>Läufe, Suite-CSV-Dateien oder Bags für den Bericht hinzufügen.</translation>
    </message>
    <message>
        <source>Computing…</source>
        <translation>Berechne …</translation>
    </message>
    <message>
        <source>The report cannot be made: %1</source>
        <translation>Der Bericht lässt sich nicht erstellen: %1</translation>
    </message>
    <message>
        <source>%1: %2 runs, %3 complete samples</source>
        <translation>%1: %2 Läufe, %3 vollständige Proben</translation>
    </message>
    <message>
        <source>Computing the report…</source>
        <translation>Berechne den Bericht …</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>cancelled; nothing written</source>
        <translation>abgebrochen; nichts geschrieben</translation>
    </message>
    <message>
        <source>Add Inputs</source>
        <translation>Eingaben hinzufügen</translation>
    </message>
    <message>
        <source>Runs, suite CSV and bags (*.%1 *.csv *.bag);;All files (*)</source>
        <translation>Läufe, Suite-CSV und Bags (*.%1 *.csv *.bag);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Pipeline</source>
        <translation>Pipeline</translation>
    </message>
    <message>
        <source>Pipelines (*.yaml *.yml);;All files (*)</source>
        <translation>Pipelines (*.yaml *.yml);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Export Report</source>
        <translation>Bericht exportieren</translation>
    </message>
    <message>
        <source>%1 files (*.%2)</source>
        <translation>%1-Dateien (*.%2)</translation>
    </message>
    <message>
        <source>Written: %1</source>
        <translation>Geschrieben: %1</translation>
    </message>
    <message>
        <source>optional; otherwise each input&apos;s own pipeline</source>
        <translation>optional; sonst die eigene Pipeline jeder Eingabe</translation>
    </message>
    <message>
        <source>a CSV file holds a single run: give one input, or tick “%1”</source>
        <translation>eine CSV-Datei enthält nur einen Lauf: eine Eingabe angeben oder „%1“ ankreuzen</translation>
    </message>
</context>
<context>
    <name>Ros2Bridge</name>
    <message>
        <source>ROS %1 -&gt; MQTT %2 (%3, %4%5)</source>
        <translation>ROS %1 -&gt; MQTT %2 (%3, %4%5)</translation>
    </message>
    <message>
        <source>, primitive</source>
        <translation>, primitiv</translation>
    </message>
    <message>
        <source>, stamped</source>
        <translation>, mit Zeitstempel</translation>
    </message>
    <message>
        <source>ignored the ROS 1 type announcement for %1 (%2): this bridge speaks ROS 2</source>
        <translation>ROS-2-Typankündigung für %2 (%2) ignoriert: diese Bridge spricht ROS 2 {1 ?} {1 ?} {2)?}</translation>
    </message>
    <message>
        <source>%1 announces %2, but the config fixes %3: kept</source>
        <translation>%1 kündigt %2 an, aber die Konfiguration legt %3 fest: beibehalten</translation>
    </message>
    <message>
        <source>MQTT %1 -&gt; ROS %2 (%3, %4)</source>
        <translation>MQTT %1 -&gt; ROS %2 (%3, %4)</translation>
    </message>
    <message>
        <source>%1: json needs a ros_type, as mqtt_client says</source>
        <translation>%1: json braucht einen ros_type, wie mqtt_client sagt</translation>
    </message>
    <message>
        <source>ROS 2 node %1 on domain %2%3</source>
        <translation>ROS-2-Knoten %1 in Domäne %2%3</translation>
    </message>
    <message>
        <source> (this host only)</source>
        <translation> (nur dieser Rechner)</translation>
    </message>
    <message>
        <source>not on the ROS 2 domain: %1</source>
        <translation>nicht in der ROS-2-Domäne: %1</translation>
    </message>
    <message>
        <source>connecting to %1…</source>
        <translation>verbinde mit %1 …</translation>
    </message>
    <message>
        <source>connected to %1</source>
        <translation>mit %1 verbunden</translation>
    </message>
    <message>
        <source>reconnected to %1</source>
        <translation>wieder mit %1 verbunden</translation>
    </message>
    <message>
        <source>lost the broker (%1); reconnecting</source>
        <translation>Broker verloren (%1); verbinde erneut</translation>
    </message>
    <message>
        <source>MQTT %1 -&gt; ROS %2: refused: the announced type changed more than %3 times in a minute (kept %4; messages of other types dropped)</source>
        <translation>MQTT %1 -&gt; ROS %2: abgelehnt: der angekündigte Typ hat sich mehr als %3-mal in einer Minute geändert (%4 behalten; Nachrichten anderer Typen verworfen)</translation>
    </message>
    <message>
        <source>ROS %1 -&gt; MQTT %2: refused: %3</source>
        <translation>ROS %1 -&gt; MQTT %2: abgelehnt: %3</translation>
    </message>
    <message>
        <source>MQTT %1 -&gt; ROS %2: refused: %3</source>
        <translation>MQTT %1 -&gt; ROS %2: abgelehnt: %3</translation>
    </message>
    <message>
        <source>ROS %1</source>
        <translation>ROS %1</translation>
    </message>
    <message>
        <source>%1: %2 (further ones are counted)</source>
        <translation>%1: %2 (weitere werden gezählt)</translation>
    </message>
    <message>
        <source>MQTT %1</source>
        <translation>MQTT %1</translation>
    </message>
    <message>
        <source>the DDS process %1; starting it again (%2)</source>
        <translation>der DDS-Prozess %1; wird neu gestartet (%2)</translation>
    </message>
</context>
<context>
    <name>Ros2BridgeWire</name>
    <message>
        <source>a payload of %1 bytes, more than the %2 MiB a json mapping converts: refused unread</source>
        <translation>Nutzdaten von %1 Bytes, mehr als die %2 MiB, die eine JSON-Zuordnung umwandelt: ungelesen abgelehnt</translation>
    </message>
</context>
<context>
    <name>Ros2Definitions</name>
    <message>
        <source>%1: more than %2 definitions; the rest were not read</source>
        <translation>%1: mehr als %2 Definitionen; der Rest wurde nicht gelesen</translation>
    </message>
    <message>
        <source>%1: not readable or over %2 KiB</source>
        <translation>%1: nicht lesbar oder über %2 KiB</translation>
    </message>
</context>
<context>
    <name>Ros2DemoNodes</name>
    <message>
        <source>the DDS process did not join the domain</source>
        <translation>der DDS-Prozess ist der Domain nicht beigetreten</translation>
    </message>
    <message>
        <source>cannot encode the point cloud</source>
        <translation>die Punktwolke lässt sich nicht kodieren</translation>
    </message>
</context>
<context>
    <name>Ros2DiscoveryInfo</name>
    <message>
        <source>not a CDR sample (its encapsulation header is missing or not plain CDR)</source>
        <translation>kein CDR-Sample (sein Kapselungskopf fehlt oder ist kein einfaches CDR)</translation>
    </message>
    <message numerus="yes">
        <source>not a ParticipantEntitiesInfo of %n byte(s): a length runs past the end, a name is over 256 characters, or bytes are left over</source>
        <translation>
            <numerusform>keine ParticipantEntitiesInfo aus %n Byte: eine Länge reicht über das Ende, ein Name hat über 256 Zeichen, oder Bytes bleiben übrig</numerusform>
            <numerusform>keine ParticipantEntitiesInfo aus %n Bytes: eine Länge reicht über das Ende, ein Name hat über 256 Zeichen, oder Bytes bleiben übrig</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>Ros2Engine</name>
    <message>
        <source>domain %1 is out of range: ROS 2 domains are 0 to %2</source>
        <translation>Domäne %1 liegt außerhalb: ROS-2-Domänen sind 0 bis %2</translation>
    </message>
    <message>
        <source>Cyclone DDS could not create a participant on domain %1 (%2: no usable network interface or ports?)</source>
        <translation>Cyclone DDS konnte auf Domäne %1 keinen Teilnehmer anlegen (%2: keine nutzbare Netzwerkschnittstelle oder Ports?)</translation>
    </message>
    <message>
        <source>%1 has no publisher or subscriber yet, so its type is not known</source>
        <translation>%1 hat noch keinen Publisher oder Subscriber, sein Typ ist also unbekannt</translation>
    </message>
    <message>
        <source>Cyclone DDS could not subscribe to %1 as %2</source>
        <translation>Cyclone DDS konnte %1 nicht als %2 abonnieren</translation>
    </message>
    <message>
        <source>not on a domain</source>
        <translation>in keiner Domäne</translation>
    </message>
</context>
<context>
    <name>Ros2Names</name>
    <message>
        <source>the type name has %1 characters (at most %2)</source>
        <translation>der Typname hat %1 Zeichen (höchstens %2)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a ROS 2 message type (pkg/msg/Type)</source>
        <translation>„%1“ ist kein ROS-2-Nachrichtentyp (pkg/msg/Type)</translation>
    </message>
    <message>
        <source>the topic name has %1 characters (at most %2)</source>
        <translation>der Topic-Name hat %1 Zeichen (höchstens %2)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a ROS 2 topic name: %2</source>
        <translation>„%1“ ist kein ROS-2-Topic-Name: %2</translation>
    </message>
</context>
<context>
    <name>Ros2Options</name>
    <message>
        <source>ROS_DOMAIN_ID is &quot;%1&quot;, not a domain from 0 to %2</source>
        <translation>ROS_DOMAIN_ID ist „%1“, keine Domäne von 0 bis %2</translation>
    </message>
    <message>
        <source>ROS_STATIC_PEERS takes at most %1 IP addresses separated by &apos;;&apos;, not &quot;%2&quot;</source>
        <translation>ROS_STATIC_PEERS erwartet höchstens %1 durch „;“ getrennte IP-Adressen, nicht „%2“</translation>
    </message>
</context>
<context>
    <name>Ros2Participant</name>
    <message>
        <source>domain %1 is out of range: ROS 2 domains are 0 to %2</source>
        <translation>Domäne %1 liegt außerhalb: ROS-2-Domänen sind 0 bis %2</translation>
    </message>
    <message>
        <source>%1 has no publisher or subscriber yet, so its type is not known</source>
        <translation>%1 hat noch keinen Publisher oder Subscriber, sein Typ ist also unbekannt</translation>
    </message>
    <message>
        <source>cannot see ROS 2: the helper program bridgescope-dds is not installed</source>
        <translation>ROS 2 nicht sichtbar: das Hilfsprogramm bridgescope-dds ist nicht installiert</translation>
    </message>
    <message>
        <source>cannot start %1: %2</source>
        <translation>%1 lässt sich nicht starten: %2</translation>
    </message>
    <message>
        <source>sent a frame of kind %1 that does not read</source>
        <translation>schickte einen unlesbaren Rahmen der Art %1</translation>
    </message>
    <message>
        <source>sent %1</source>
        <translation>schickte %1</translation>
    </message>
    <message>
        <source>sent nothing for %1 s</source>
        <translation>schickte %1 s lang nichts</translation>
    </message>
    <message>
        <source>did not start: %1</source>
        <translation>startete nicht: %1</translation>
    </message>
    <message>
        <source>crashed (signal %1)</source>
        <translation>stürzte ab (Signal %1)</translation>
    </message>
    <message>
        <source>ended with exit code %1</source>
        <translation>endete mit Exit-Code %1</translation>
    </message>
    <message numerus="yes">
        <source>%n endpoint(s) not listed (over a bound)</source>
        <translation>
            <numerusform>%n Endpunkt nicht aufgeführt (über einer Grenze)</numerusform>
            <numerusform>%n Endpunkte nicht aufgeführt (über einer Grenze)</numerusform>
        </translation>
    </message>
    <message>
        <source>the DDS process %1 while making it: quarantined, not asked again</source>
        <translation>der DDS-Prozess %1, während er es anlegte: unter Quarantäne, wird nicht erneut angefragt</translation>
    </message>
    <message numerus="yes">
        <source>ROS 2 discovery restarted %n time(s), %1 caused by peers (last: %2)</source>
        <translation>
            <numerusform>ROS-2-Erkennung %n-mal neu gestartet, %1 durch Teilnehmer verursacht (zuletzt: %2)</numerusform>
            <numerusform>ROS-2-Erkennung %n-mal neu gestartet, %1 durch Teilnehmer verursacht (zuletzt: %2)</numerusform>
        </translation>
    </message>
    <message>
        <source>a restart loop broken: the graph limited</source>
        <translation>eine Neustart-Schleife durchbrochen: der Graph begrenzt</translation>
    </message>
    <message numerus="yes">
        <source>%n ROS 2 request(s) quarantined (last: %1)</source>
        <translation>
            <numerusform>%n ROS-2-Anfrage(n) unter Quarantäne (zuletzt: %1)</numerusform>
            <numerusform>%n ROS-2-Anfrage(n) unter Quarantäne (zuletzt: %1)</numerusform>
        </translation>
    </message>
    <message>
        <source>a restart loop: %1 restarts in a row, none explained by a request; the DDS process is started again with the graph limited (%2 endpoints a participant, %3 in all)</source>
        <translation>eine Neustart-Schleife: %1 Neustarts in Folge, keiner durch eine Anfrage erklärt; der DDS-Prozess wird mit begrenztem Graphen neu gestartet (%2 Endpunkte je Teilnehmer, %3 insgesamt)</translation>
    </message>
</context>
<context>
    <name>Ros2Protocol</name>
    <message>
        <source>a frame of %1 bytes (at most %2)</source>
        <translation>einen Rahmen von %1 Bytes (höchstens %2)</translation>
    </message>
    <message>
        <source>a frame of unknown kind %1</source>
        <translation>einen Rahmen unbekannter Art %1</translation>
    </message>
</context>
<context>
    <name>Ros2Qos</name>
    <message>
        <source>the subscriber asks for reliable delivery, the publisher offers best effort</source>
        <translation>der Subscriber verlangt zuverlässige Zustellung, der Publisher bietet Best Effort</translation>
    </message>
    <message>
        <source>the subscriber asks for %1 durability, the publisher offers %2</source>
        <translation>der Subscriber verlangt Dauerhaftigkeit %1, der Publisher bietet %2</translation>
    </message>
</context>
<context>
    <name>RosEndpoint</name>
    <message>
        <source>no ROS master answers at %1</source>
        <translation>unter %1 antwortet kein ROS-Master</translation>
    </message>
    <message>
        <source>the ROS master does not answer; waiting for it</source>
        <translation>der ROS-Master antwortet nicht; warte auf ihn</translation>
    </message>
    <message>
        <source>the ROS master was restarted: %1</source>
        <translation>der ROS-Master wurde neu gestartet: %1</translation>
    </message>
    <message>
        <source>cannot register with the ROS master again: %1</source>
        <translation>kann sich nicht erneut beim ROS-Master anmelden: %1</translation>
    </message>
    <message>
        <source>the ROS master answers again</source>
        <translation>der ROS-Master antwortet wieder</translation>
    </message>
    <message>
        <source>this node already publishes %1 with another type</source>
        <translation>dieser Knoten veröffentlicht %1 bereits mit einem anderen Typ</translation>
    </message>
</context>
<context>
    <name>RosMasterApi</name>
    <message>
        <source>an integer that is none</source>
        <translation>eine Ganzzahl, die keine ist</translation>
    </message>
    <message>
        <source>unexpected &lt;%1&gt; in an array</source>
        <translation>unerwartetes &lt;%1&gt; in einem Array</translation>
    </message>
    <message>
        <source>unknown XML-RPC type &lt;%1&gt;</source>
        <translation>unbekannter XML-RPC-Typ &lt;%1&gt;</translation>
    </message>
    <message>
        <source>the response ends inside a value</source>
        <translation>die Antwort endet mitten in einem Wert</translation>
    </message>
    <message>
        <source>XML-RPC fault %1: %2</source>
        <translation>XML-RPC-Fehler %1: %2</translation>
    </message>
    <message>
        <source>malformed XML-RPC response: %1</source>
        <translation>fehlerhafte XML-RPC-Antwort: %1</translation>
    </message>
    <message>
        <source>the XML-RPC response holds no value</source>
        <translation>die XML-RPC-Antwort enthält keinen Wert</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a ROS master URI (http://host:11311)</source>
        <translation>&apos;%1&apos; ist keine ROS-Master-URI (http://host:11311)</translation>
    </message>
    <message>
        <source>no ROS master at %1: %2</source>
        <translation>kein ROS-Master unter %1: %2</translation>
    </message>
    <message>
        <source>the ROS master at %1 did not answer within %2 ms</source>
        <translation>der ROS-Master unter %1 antwortete nicht binnen %2 ms</translation>
    </message>
    <message>
        <source>the ROS master at %1 sent no HTTP response</source>
        <translation>der ROS-Master unter %1 schickte keine HTTP-Antwort</translation>
    </message>
    <message>
        <source>the ROS master at %1 answered %2</source>
        <translation>der ROS-Master unter %1 antwortete %2</translation>
    </message>
    <message>
        <source>the ROS master&apos;s answer to %1 is not [code, status, value]</source>
        <translation>die Antwort des ROS-Masters auf %1 ist nicht [Code, Status, Wert]</translation>
    </message>
    <message>
        <source>the ROS master refused %1: %2</source>
        <translation>der ROS-Master lehnte %1 ab: %2</translation>
    </message>
    <message>
        <source>the ROS master at %1 sent more than %2 MiB</source>
        <translation>der ROS-Master unter %1 hat mehr als %2 MiB gesendet</translation>
    </message>
</context>
<context>
    <name>RosMessageDecoder</name>
    <message>
        <source>byte %1: %2</source>
        <translation>Byte %1: %2</translation>
    </message>
    <message>
        <source>the message ends while reading &apos;%1&apos; (needs %2 more bytes, %3 left)</source>
        <translation>die Nachricht endet beim Lesen von &apos;%1&apos; (braucht %2 weitere Bytes, %3 übrig)</translation>
    </message>
    <message>
        <source>unknown type &apos;%1&apos;</source>
        <translation>unbekannter Typ &apos;%1&apos;</translation>
    </message>
    <message>
        <source>nested deeper than %1 levels</source>
        <translation>tiefer als %1 Ebenen verschachtelt</translation>
    </message>
    <message>
        <source>no definition for &apos;%1&apos;</source>
        <translation>keine Definition für &apos;%1&apos;</translation>
    </message>
    <message>
        <source>%1 bytes left over after the message</source>
        <translation>%1 Bytes bleiben nach der Nachricht übrig</translation>
    </message>
    <message>
        <source>more than %1 steps (fields and array elements): too much work for one message</source>
        <translation>mehr als %1 Schritte (Felder und Array-Elemente): zu viel Arbeit für eine Nachricht</translation>
    </message>
    <message>
        <source>&apos;%1&apos; claims %2 elements of at least %3 bytes, but only %4 bytes are left</source>
        <translation>&apos;%1&apos; gibt %2 Elemente zu mindestens %3 Bytes an, aber nur %4 Bytes sind übrig</translation>
    </message>
    <message>
        <source>more than %1 values to show: too much work for one message</source>
        <translation>mehr als %1 Werte zum Anzeigen: zu viel Arbeit für eine Nachricht</translation>
    </message>
    <message>
        <source>the message has %1 bytes, more than the %2 bytes one message may have</source>
        <translation>die Nachricht hat %1 Bytes, mehr als die %2 Bytes, die eine Nachricht haben darf</translation>
    </message>
    <message>
        <source>padding</source>
        <translation>Auffüllbytes</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is a wstring, which is not decoded</source>
        <translation>&apos;%1&apos; ist ein wstring, der nicht dekodiert wird</translation>
    </message>
    <message>
        <source>the CDR encapsulation header</source>
        <translation>den CDR-Kapselungskopf</translation>
    </message>
    <message>
        <source>not plain CDR (encapsulation %1 %2)</source>
        <translation>kein einfaches CDR (Kapselung %1 %2)</translation>
    </message>
</context>
<context>
    <name>RosMessageEncoder</name>
    <message>
        <source>a map</source>
        <translation>eine Map</translation>
    </message>
    <message>
        <source>a list</source>
        <translation>eine Liste</translation>
    </message>
    <message>
        <source>a bool</source>
        <translation>ein Bool</translation>
    </message>
    <message>
        <source>the text &apos;%1&apos;</source>
        <translation>der Text &apos;%1&apos;</translation>
    </message>
    <message>
        <source>a number</source>
        <translation>eine Zahl</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>more than %1 values: too much for one message</source>
        <translation>mehr als %1 Werte: zu viel für eine Nachricht</translation>
    </message>
    <message>
        <source>nested deeper than %1 levels</source>
        <translation>tiefer als %1 Ebenen verschachtelt</translation>
    </message>
    <message>
        <source>no definition for &apos;%1&apos;</source>
        <translation>keine Definition für &apos;%1&apos;</translation>
    </message>
    <message>
        <source>%1 is a message and needs a map of its fields, not %2</source>
        <translation>%1 ist eine Nachricht und braucht eine Map ihrer Felder, nicht %2</translation>
    </message>
    <message>
        <source>%1 has no field &apos;%2&apos;</source>
        <translation>%1 hat kein Feld &apos;%2&apos;</translation>
    </message>
    <message>
        <source>an array needs a list, not %1</source>
        <translation>ein Array braucht eine Liste, nicht %1</translation>
    </message>
    <message>
        <source>has %1 elements, the type fixes %2</source>
        <translation>hat %1 Elemente, der Typ legt %2 fest</translation>
    </message>
    <message>
        <source>%1 elements: too many for one message</source>
        <translation>%1 Elemente: zu viele für eine Nachricht</translation>
    </message>
    <message>
        <source>the message would pass %1 bytes</source>
        <translation>die Nachricht würde %1 Bytes überschreiten</translation>
    </message>
    <message>
        <source>%1 is not a whole number</source>
        <translation>%1 ist keine ganze Zahl</translation>
    </message>
    <message>
        <source>%1 is out of range</source>
        <translation>%1 liegt außerhalb des Bereichs</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a whole number</source>
        <translation>&apos;%1&apos; ist keine ganze Zahl</translation>
    </message>
    <message>
        <source>needs a whole number, not %1</source>
        <translation>braucht eine ganze Zahl, nicht %1</translation>
    </message>
    <message>
        <source>%1%2 does not fit %3 (%4 to %5)</source>
        <translation>%1%2 passt nicht in %3 (%4 bis %5)</translation>
    </message>
    <message>
        <source>%1%2 does not fit %3 (0 to %4)</source>
        <translation>%1%2 passt nicht in %3 (0 bis %4)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a number</source>
        <translation>&apos;%1&apos; ist keine Zahl</translation>
    </message>
    <message>
        <source>needs a number, not %1</source>
        <translation>braucht eine Zahl, nicht %1</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not true or false</source>
        <translation>&apos;%1&apos; ist weder true noch false</translation>
    </message>
    <message>
        <source>%1 is not a bool (0 or 1)</source>
        <translation>%1 ist kein Bool (0 oder 1)</translation>
    </message>
    <message>
        <source>needs true or false, not %1</source>
        <translation>braucht true oder false, nicht %1</translation>
    </message>
    <message>
        <source>a time has secs and nsecs, not &apos;%1&apos;</source>
        <translation>eine Zeit hat secs und nsecs, nicht &apos;%1&apos;</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a time in seconds (sec.nsec, at most nine decimals)</source>
        <translation>&apos;%1&apos; ist keine Zeit in Sekunden (sec.nsec, höchstens neun Nachkommastellen)</translation>
    </message>
    <message>
        <source>%1 seconds is out of range</source>
        <translation>%1 Sekunden liegen außerhalb des Bereichs</translation>
    </message>
    <message>
        <source>needs a time (sec.nsec), not %1</source>
        <translation>braucht eine Zeit (sec.nsec), nicht %1</translation>
    </message>
    <message>
        <source>needs text, not %1</source>
        <translation>braucht Text, nicht %1</translation>
    </message>
    <message>
        <source>%1 does not fit float32</source>
        <translation>%1 passt nicht in float32</translation>
    </message>
    <message>
        <source>a time must lie between 0 and 4294967295 seconds</source>
        <translation>eine Zeit muss zwischen 0 und 4294967295 Sekunden liegen</translation>
    </message>
    <message>
        <source>a duration must lie within ±2147483647 seconds</source>
        <translation>eine Dauer muss innerhalb von ±2147483647 Sekunden liegen</translation>
    </message>
    <message>
        <source>unknown type &apos;%1&apos;</source>
        <translation>unbekannter Typ &apos;%1&apos;</translation>
    </message>
    <message>
        <source>text with a NUL character cannot be sent as a CDR string</source>
        <translation>Text mit einem NUL-Zeichen kann nicht als CDR-String gesendet werden</translation>
    </message>
</context>
<context>
    <name>RosOptions</name>
    <message>
        <source>Which ROS graphs: 1 (through the master), 2 (through DDS) or both (default %1).</source>
        <translation>Welche ROS-Graphen: 1 (über den Master), 2 (über DDS) oder both (beide; Standard %1).</translation>
    </message>
    <message>
        <source>ROS 2 domain id, 0 to 232 (default $ROS_DOMAIN_ID, else 0).</source>
        <translation>ROS-2-Domänen-ID, 0 bis 232 (Standard $ROS_DOMAIN_ID, sonst 0).</translation>
    </message>
    <message>
        <source>ROS 2 discovery on this host only, over 127.0.0.1 (as ROS_LOCALHOST_ONLY=1).</source>
        <translation>ROS-2-Erkennung nur auf diesem Rechner, über 127.0.0.1 (wie ROS_LOCALHOST_ONLY=1).</translation>
    </message>
    <message>
        <source>--ros takes 1, 2 or both, not &quot;%1&quot;</source>
        <translation>--ros erwartet 1, 2 oder both, nicht „%1“</translation>
    </message>
    <message>
        <source>--ros-domain takes a domain id from 0 to %1</source>
        <translation>--ros-domain erwartet eine Domänen-ID von 0 bis %1</translation>
    </message>
    <message>
        <source>ROS_VERSION is &quot;%1&quot;, not 1 or 2: ignored</source>
        <translation>ROS_VERSION ist „%1“, nicht 1 oder 2: nicht beachtet</translation>
    </message>
    <message>
        <source>ROS_DISTRO is &quot;%1&quot;, not a ROS distribution known here: ignored</source>
        <translation>ROS_DISTRO ist „%1“, keine hier bekannte ROS-Distribution: nicht beachtet</translation>
    </message>
    <message>
        <source>ROS 1 and ROS 2</source>
        <translation>ROS 1 und ROS 2</translation>
    </message>
    <message>
        <source>ROS 2</source>
        <translation>ROS 2</translation>
    </message>
    <message>
        <source>ROS 1</source>
        <translation>ROS 1</translation>
    </message>
    <message>
        <source>default</source>
        <translation>Standard</translation>
    </message>
    <message>
        <source>domain %1</source>
        <translation>Domain %1</translation>
    </message>
    <message>
        <source>this host only</source>
        <translation>nur dieser Rechner</translation>
    </message>
</context>
<context>
    <name>RosReregistration</name>
    <message>
        <source>cannot list this node&apos;s topics</source>
        <translation>die Topics dieses Knotens lassen sich nicht auflisten</translation>
    </message>
    <message>
        <source>the master refused %1</source>
        <translation>der Master hat %1 abgelehnt</translation>
    </message>
    <message numerus="yes">
        <source>%n topic(s) registered again</source>
        <translation>
            <numerusform>%n Topic erneut angemeldet</numerusform>
            <numerusform>%n Topics erneut angemeldet</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>RosStampSource</name>
    <message>
        <source>a %1, not a benchmarking_suite/TimeStamped</source>
        <translation>ein %1, kein benchmarking_suite/TimeStamped</translation>
    </message>
    <message>
        <source>a %1, not a std_msgs/Float64</source>
        <translation>ein %1, kein std_msgs/Float64</translation>
    </message>
</context>
<context>
    <name>RosTypeRegistry</name>
    <message>
        <source>line %1: expected &apos;MSG: package/Type&apos; after the separator</source>
        <translation>Zeile %1: nach dem Trenner wird &apos;MSG: paket/Typ&apos; erwartet</translation>
    </message>
    <message>
        <source>line %1: &apos;%2&apos; is not &apos;type name&apos;</source>
        <translation>Zeile %1: &apos;%2&apos; ist nicht &apos;typ name&apos;</translation>
    </message>
    <message>
        <source>line %1: bad array type &apos;%2&apos;</source>
        <translation>Zeile %1: fehlerhafter Array-Typ &apos;%2&apos;</translation>
    </message>
    <message>
        <source>line %1: field without a name</source>
        <translation>Zeile %1: Feld ohne Namen</translation>
    </message>
    <message>
        <source>line %1: a field name of %2 characters (at most %3)</source>
        <translation>Zeile %1: ein Feldname mit %2 Zeichen (höchstens %3)</translation>
    </message>
</context>
<context>
    <name>RosbagImport</name>
    <message>
        <source>no %1 topics in the bag (it has: %2)</source>
        <translation>keine Topics vom Typ %1 im Bag (vorhanden: %2)</translation>
    </message>
    <message>
        <source>nothing</source>
        <translation>nichts</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>%1 messages of the stamp types did not decode and were skipped.</source>
        <translation>%1 Nachrichten der Zeitstempel-Typen ließen sich nicht dekodieren und wurden übersprungen.</translation>
    </message>
    <message>
        <source>cannot read the bag: %1</source>
        <translation>das Bag ist nicht lesbar: %1</translation>
    </message>
</context>
<context>
    <name>Rules</name>
    <message>
        <source>Prints the Prometheus rules for the metrics of watch --metrics: recording rules per link, bridge and host, and alerts (a bridge down, a link in alert or stalled, loss over 1 %, latency p99 over 100 ms, a host&apos;s watch gone). Save them where Prometheus reads its rule_files:
  bridgescope rules &gt; /etc/prometheus/bridgescope-rules.yml
Exit status: 0 printed, 2 bad arguments or standard output cannot be written.</source>
        <translation>Gibt die Prometheus-Regeln für die Metriken von watch --metrics aus: Aufzeichnungsregeln je Verbindung, Bridge und Rechner, und Alarme (eine Bridge ausgefallen, eine Verbindung im Alarm oder ins Stocken geraten, Verlust über 1 %, Latenz-p99 über 100 ms, die Überwachung eines Rechners verschwunden). Dort speichern, wo Prometheus seine rule_files liest:
  bridgescope rules &gt; /etc/prometheus/bridgescope-rules.yml
Exit-Status: 0 ausgegeben, 2 falsche Argumente oder die Standardausgabe ist nicht beschreibbar.</translation>
    </message>
    <message>
        <source>rules takes no arguments; see bridgescope rules --help</source>
        <translation>rules erwartet keine Argumente; siehe bridgescope rules --help</translation>
    </message>
    <message>
        <source>error: the rules are not in this build: %1</source>
        <translation>Fehler: die Regeln fehlen in diesem Build: %1</translation>
    </message>
</context>
<context>
    <name>RulesEditor</name>
    <message>
        <source>Watch Rules</source>
        <translation>Überwachungsregeln</translation>
    </message>
    <message>
        <source>Settings: latency_p99_ms, min_rate_hz, min_rate_percent, max_loss_percent, stall_seconds, stall_periods, source_stopped_seconds. A number is the alert level; {warning: N, alert: N} sets both. Entries under links match a glob on the ROS or MQTT topic, client:ID or config:NAME.</source>
        <translation>Einstellungen: latency_p99_ms, min_rate_hz, min_rate_percent, max_loss_percent, stall_seconds, stall_periods, source_stopped_seconds. Eine Zahl ist die Alarmstufe; {warning: N, alert: N} setzt beide. Einträge unter links passen per Platzhalter auf das ROS- oder MQTT-Topic, client:ID oder config:NAME.</translation>
    </message>
    <message>
        <source>&amp;Apply</source>
        <translation>&amp;Anwenden</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>Ö&amp;ffnen…</translation>
    </message>
    <message>
        <source>&amp;Save As…</source>
        <translation>&amp;Speichern unter…</translation>
    </message>
    <message numerus="yes">
        <source>Valid: %n override(s) after the defaults.</source>
        <translation>
            <numerusform>Gültig: %n Ausnahme nach den Vorgaben.</numerusform>
            <numerusform>Gültig: %n Ausnahmen nach den Vorgaben.</numerusform>
        </translation>
    </message>
    <message>
        <source>Open Watch Rules</source>
        <translation>Überwachungsregeln öffnen</translation>
    </message>
    <message>
        <source>Rules (*.yaml *.yml);;All files (*)</source>
        <translation>Regeln (*.yaml *.yml);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Save Watch Rules</source>
        <translation>Überwachungsregeln speichern</translation>
    </message>
</context>
<context>
    <name>RunBar</name>
    <message>
        <source>● Re&amp;cord…</source>
        <translation>● A&amp;ufzeichnen …</translation>
    </message>
    <message>
        <source>Open R&amp;un…</source>
        <translation>Lauf &amp;öffnen …</translation>
    </message>
    <message>
        <source>Record every stamp from now on into a run file, to open, compare and report later</source>
        <translation>Ab jetzt jeden Zeitstempel in eine Laufdatei aufzeichnen, um den Lauf später zu öffnen, zu vergleichen und auszuwerten</translation>
    </message>
    <message>
        <source>Show a recorded run as it was, or import the suite&apos;s timestamp CSV or a ROS bag</source>
        <translation>Einen aufgezeichneten Lauf so zeigen, wie er war, oder die Zeitstempel-CSV der Suite oder ein ROS-Bag importieren</translation>
    </message>
    <message>
        <source>Save the run on screen (an imported CSV or bag) as a Bridgescope run</source>
        <translation>Den angezeigten Lauf (eine importierte CSV oder ein Bag) als Bridgescope-Lauf speichern</translation>
    </message>
    <message>
        <source>Recording Stopped</source>
        <translation>Aufzeichnung gestoppt</translation>
    </message>
    <message>
        <source>The run file could not be written: %1
What was committed before is kept.</source>
        <translation>Die Laufdatei ließ sich nicht schreiben: %1
Was zuvor festgeschrieben wurde, bleibt erhalten.</translation>
    </message>
    <message>
        <source>Stop Recording</source>
        <translation>Aufzeichnung beenden</translation>
    </message>
    <message>
        <source>Record a Run</source>
        <translation>Lauf aufzeichnen</translation>
    </message>
    <message>
        <source>Reading %1…</source>
        <translation>Lese %1 …</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Open Run</source>
        <translation>Lauf öffnen</translation>
    </message>
    <message>
        <source>no run on screen</source>
        <translation>kein Lauf angezeigt</translation>
    </message>
    <message>
        <source>Writing %1…</source>
        <translation>Schreibe %1 …</translation>
    </message>
    <message>
        <source>Runs, suite CSV and bags (*.%1 *.csv *.bag);;All files (*)</source>
        <translation>Läufe, Suite-CSV und Bags (*.%1 *.csv *.bag);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Save Run As</source>
        <translation>Lauf speichern unter</translation>
    </message>
    <message>
        <source>Bridgescope runs (*.%1)</source>
        <translation>Bridgescope-Läufe (*.%1)</translation>
    </message>
    <message>
        <source>■ Stop Re&amp;cording</source>
        <translation>■ A&amp;ufzeichnung beenden</translation>
    </message>
    <message>
        <source>&lt;b&gt;Recording&lt;/b&gt; %1: %2 stamps committed to %3</source>
        <translation>&lt;b&gt;Aufzeichnung&lt;/b&gt; %1: %2 Zeitstempel in %3 festgeschrieben</translation>
    </message>
    <message>
        <source>unknown time</source>
        <translation>unbekannte Zeit</translation>
    </message>
    <message>
        <source>&lt;b&gt;Showing the run&lt;/b&gt; %1 (%2, %3): live stamps are not measured meanwhile</source>
        <translation>&lt;b&gt;Angezeigter Lauf&lt;/b&gt; %1 (%2, %3): Live-Zeitstempel werden währenddessen nicht gemessen</translation>
    </message>
    <message>
        <source>Live</source>
        <translation>Live</translation>
    </message>
    <message>
        <source>Save Ru&amp;n As…</source>
        <translation>Lauf speichern u&amp;nter …</translation>
    </message>
    <message>
        <source>&amp;Back to Live</source>
        <translation>Zu&amp;rück zu Live</translation>
    </message>
    <message>
        <source>%1 rows could not be read and were skipped:
%2</source>
        <translation>%1 Zeilen waren nicht lesbar und wurden übersprungen:
%2</translation>
    </message>
    <message>
        <source>stamp</source>
        <translation>Zeitstempel</translation>
    </message>
</context>
<context>
    <name>RunFile</name>
    <message>
        <source>not a Bridgescope run (not an SQLite database)</source>
        <translation>kein Bridgescope-Lauf (keine SQLite-Datenbank)</translation>
    </message>
    <message>
        <source>not a Bridgescope run (%1)</source>
        <translation>kein Bridgescope-Lauf (%1)</translation>
    </message>
    <message>
        <source>not a Bridgescope run (no run metadata)</source>
        <translation>kein Bridgescope-Lauf (keine Laufmetadaten)</translation>
    </message>
    <message>
        <source>written by a newer Bridgescope (run format %1, this one reads %2)</source>
        <translation>von einem neueren Bridgescope geschrieben (Laufformat %1, diese Version liest %2)</translation>
    </message>
    <message>
        <source>stamp %1 names a topic the run does not have</source>
        <translation>Zeitstempel %1 nennt ein Topic, das der Lauf nicht hat</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>a latency names a series the run does not have</source>
        <translation>eine Latenz nennt eine Reihe, die der Lauf nicht hat</translation>
    </message>
    <message>
        <source>%1: cannot replace it (%2)</source>
        <translation>%1: lässt sich nicht ersetzen (%2)</translation>
    </message>
    <message>
        <source>its pipeline cannot be read: %1</source>
        <translation>seine Pipeline ist nicht lesbar: %1</translation>
    </message>
    <message>
        <source>refused: reading it takes more than %1 SQLite steps (a run file of its size needs far fewer)</source>
        <translation>abgelehnt: das Lesen braucht mehr als %1 SQLite-Schritte (eine Lauf-Datei dieser Größe braucht weit weniger)</translation>
    </message>
    <message>
        <source>refused: reading it takes more than %1 s</source>
        <translation>abgelehnt: das Lesen dauert länger als %1 s</translation>
    </message>
    <message>
        <source>refused: it has more than %1 rows (the most a run file may have)</source>
        <translation>abgelehnt: sie hat mehr als %1 Zeilen (das Höchste, was eine Lauf-Datei haben darf)</translation>
    </message>
    <message>
        <source>refused: it has more than %1 MiB of text (the most a run file may have)</source>
        <translation>abgelehnt: sie hat mehr als %1 MiB Text (das Höchste, was eine Lauf-Datei haben darf)</translation>
    </message>
    <message>
        <source>it holds more than %1 objects</source>
        <translation>sie enthält mehr als %1 Objekte</translation>
    </message>
    <message>
        <source>%1 &quot;%2&quot; is not one of its tables</source>
        <translation>%1 &quot;%2&quot; ist keine ihrer Tabellen</translation>
    </message>
    <message>
        <source>not a Bridgescope run, refused: %1</source>
        <translation>kein Bridgescope-Lauf, abgelehnt: %1</translation>
    </message>
    <message>
        <source>not a Bridgescope run, refused: table &quot;%1&quot; has the columns %2, not %3</source>
        <translation>kein Bridgescope-Lauf, abgelehnt: Tabelle &quot;%1&quot; hat die Spalten %2, nicht %3</translation>
    </message>
    <message>
        <source>cannot read it: the SQLite driver gives no handle to set its limits</source>
        <translation>kann sie nicht lesen: der SQLite-Treiber gibt kein Handle, um seine Grenzen zu setzen</translation>
    </message>
    <message>
        <source>its write-ahead log %1 is %2, not a file: refused</source>
        <translation>ihr Write-Ahead-Log %1 ist %2, keine Datei: abgelehnt</translation>
    </message>
</context>
<context>
    <name>RunLoader</name>
    <message>
        <source>%1: a pipeline needs at least two stamp topics, the file has %2</source>
        <translation>%1: eine Pipeline braucht mindestens zwei Zeitstempel-Topics, die Datei hat %2</translation>
    </message>
    <message>
        <source>run</source>
        <translation>Lauf</translation>
    </message>
    <message>
        <source>ROS bag</source>
        <translation>ROS-Bag</translation>
    </message>
    <message>
        <source>suite CSV</source>
        <translation>Suite-CSV</translation>
    </message>
    <message>
        <source>%1 rows that did not read were skipped.</source>
        <translation>%1 nicht lesbare Zeilen wurden übersprungen.</translation>
    </message>
    <message>
        <source> (and %1 more rows that cannot be read)</source>
        <translation> (und %1 weitere nicht lesbare Zeilen)</translation>
    </message>
    <message>
        <source>%1: %2 %3 (%4), %5: %6 is %7</source>
        <translation>%1: %2 %3 (%4), %5: %6 ist %7</translation>
    </message>
    <message>
        <source>latency</source>
        <translation>Latenz</translation>
    </message>
    <message>
        <source>stamp</source>
        <translation>Zeitstempel</translation>
    </message>
    <message>
        <source>larger than any difference of two ROS times</source>
        <translation>größer als jede Differenz zweier ROS-Zeiten</translation>
    </message>
    <message>
        <source> (and %1 more values out of range)</source>
        <translation> (und %1 weitere Werte außerhalb des Bereichs)</translation>
    </message>
    <message>
        <source>%1: %2 rows begin with the same stamp as an earlier row; each counts as a sample of its own, but cannot be joined with another file</source>
        <translation>%1: %2 Zeilen beginnen mit demselben Stempel wie eine frühere Zeile; jede zählt als eigenes Sample, lässt sich aber nicht mit einer anderen Datei verbinden</translation>
    </message>
</context>
<context>
    <name>RunRecorder</name>
    <message>
        <source>already recording to %1</source>
        <translation>zeichnet bereits in %1 auf</translation>
    </message>
</context>
<context>
    <name>RunWriter</name>
    <message>
        <source>%1 exists already; a run is never overwritten</source>
        <translation>%1 existiert bereits; ein Lauf wird nie überschrieben</translation>
    </message>
    <message>
        <source>%1: cannot create its folder</source>
        <translation>%1: Ordner lässt sich nicht anlegen</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>SettingsInspector</name>
    <message>
        <source>&lt;b&gt;Broker&lt;/b&gt;</source>
        <translation>&lt;b&gt;Broker&lt;/b&gt;</translation>
    </message>
    <message>
        <source>&lt;b&gt;Client&lt;/b&gt;</source>
        <translation>&lt;b&gt;Client&lt;/b&gt;</translation>
    </message>
    <message>
        <source>Set %1.%2</source>
        <translation>%1.%2 setzen</translation>
    </message>
</context>
<context>
    <name>SourceCheck</name>
    <message>
        <source>the broker %1 is reached</source>
        <translation>der Broker %1 ist erreichbar</translation>
    </message>
    <message>
        <source>the broker %1 cannot be reached (%2); still trying</source>
        <translation>der Broker %1 ist nicht erreichbar (%2); versucht es weiter</translation>
    </message>
    <message>
        <source>the ROS master %1 is reached</source>
        <translation>der ROS-Master %1 ist erreichbar</translation>
    </message>
    <message>
        <source>the ROS master %1 cannot be reached (%2); still trying</source>
        <translation>der ROS-Master %1 ist nicht erreichbar (%2); versucht es weiter</translation>
    </message>
    <message>
        <source>%1; still waiting</source>
        <translation>%1; wartet weiter</translation>
    </message>
    <message>
        <source>neither the broker nor the master was reached, and nobody was heard on ROS 2 domain %1</source>
        <translation>weder Broker noch Master waren erreichbar, und in der ROS-2-Domäne %1 war niemand zu hören</translation>
    </message>
    <message>
        <source>the broker was not reached and nobody was heard on ROS 2 domain %1</source>
        <translation>der Broker war nicht erreichbar, und in der ROS-2-Domäne %1 war niemand zu hören</translation>
    </message>
    <message>
        <source>neither the broker nor the master was reached</source>
        <translation>weder Broker noch Master waren erreichbar</translation>
    </message>
    <message>
        <source>the broker was not reached</source>
        <translation>der Broker war nicht erreichbar</translation>
    </message>
    <message>
        <source>ROS 2 discovery restarted: the DDS process %1</source>
        <translation>ROS-2-Erkennung neu gestartet: der DDS-Prozess %1</translation>
    </message>
</context>
<context>
    <name>SourceMessage</name>
    <message>
        <source>no ROS type was announced for it</source>
        <translation>dafür wurde kein ROS-Typ angekündigt</translation>
    </message>
    <message>
        <source>a latency that is no finite number of seconds</source>
        <translation>eine Latenz, die keine endliche Zahl von Sekunden ist</translation>
    </message>
</context>
<context>
    <name>SshCommand</name>
    <message>
        <source>no program to run on the far host</source>
        <translation>kein Programm zum Ausführen auf dem entfernten Host</translation>
    </message>
    <message>
        <source>a word for the far host holds a NUL character</source>
        <translation>ein Wort für den entfernten Host enthält ein NUL-Zeichen</translation>
    </message>
    <message>
        <source>the known-hosts file &quot;%1&quot; has white space, quotes, &apos;%&apos; or &apos;\&apos; in its name, which ssh&apos;s options cannot carry</source>
        <translation>die Known-Hosts-Datei &quot;%1&quot; hat Leerraum, Anführungszeichen, &apos;%&apos; oder &apos;\&apos; im Namen, was die Optionen von ssh nicht tragen können</translation>
    </message>
    <message>
        <source>cannot reach %1 (%2): %3</source>
        <translation>%1 (%2) nicht erreichbar: %3</translation>
    </message>
    <message>
        <source>cannot run on %1 (%2): %3</source>
        <translation>kann auf %1 (%2) nicht ausführen: %3</translation>
    </message>
    <message>
        <source>cannot start %1 for %2 (%3): %4</source>
        <translation>kann %1 für %2 (%3) nicht starten: %4</translation>
    </message>
</context>
<context>
    <name>StampCodec</name>
    <message>
        <source>TimeStamped message too short (%1 bytes)</source>
        <translation>TimeStamped-Nachricht zu kurz (%1 Bytes)</translation>
    </message>
    <message>
        <source>TimeStamped frame_id claims %1 bytes, only %2 left</source>
        <translation>TimeStamped-frame_id gibt %1 Bytes an, nur %2 übrig</translation>
    </message>
    <message>
        <source>TimeStamped message ends before its time field</source>
        <translation>TimeStamped-Nachricht endet vor ihrem Feld time</translation>
    </message>
    <message>
        <source>TimeStamped message has %1 bytes too many</source>
        <translation>TimeStamped-Nachricht hat %1 Bytes zu viel</translation>
    </message>
    <message>
        <source>not JSON: %1 at byte %2</source>
        <translation>kein JSON: %1 bei Byte %2</translation>
    </message>
    <message>
        <source>JSON stamp must be an object</source>
        <translation>ein JSON-Zeitstempel muss ein Objekt sein</translation>
    </message>
    <message>
        <source>JSON stamp needs &quot;sample&quot; and &quot;time&quot;</source>
        <translation>ein JSON-Zeitstempel braucht &quot;sample&quot; und &quot;time&quot;</translation>
    </message>
    <message>
        <source>JSON stamp&apos;s &quot;sample&quot; must be a string or a number</source>
        <translation>&quot;sample&quot; des JSON-Zeitstempels muss eine Zeichenkette oder Zahl sein</translation>
    </message>
    <message>
        <source>JSON stamp&apos;s &quot;time&quot; must be seconds or &quot;sec.nsec&quot;</source>
        <translation>&quot;time&quot; des JSON-Zeitstempels muss Sekunden oder &quot;sek.nsek&quot; sein</translation>
    </message>
    <message>
        <source>outside the times a ROS stamp can hold (0 to 4294967296 s after 1970)</source>
        <translation>außerhalb der Zeiten, die ein ROS-Zeitstempel fassen kann (0 bis 4294967296 s nach 1970)</translation>
    </message>
    <message>
        <source>JSON stamp of %1 bytes: a stamp has at most %2</source>
        <translation>JSON-Zeitstempel mit %1 Bytes: ein Zeitstempel hat höchstens %2</translation>
    </message>
    <message>
        <source>JSON stamp&apos;s &quot;sample&quot; is not a usable number (%1)</source>
        <translation>&quot;sample&quot; des JSON-Zeitstempels ist keine brauchbare Zahl (%1)</translation>
    </message>
    <message>
        <source>JSON stamp&apos;s &quot;time&quot; %1 is %2</source>
        <translation>&quot;time&quot; %1 des JSON-Zeitstempels ist %2</translation>
    </message>
    <message>
        <source>TimeStamped header stamp has %1 nanoseconds, more than a second</source>
        <translation>Der Header-Stempel der TimeStamped-Nachricht hat %1 Nanosekunden, mehr als eine Sekunde</translation>
    </message>
    <message>
        <source>TimeStamped time has %1 nanoseconds, more than a second</source>
        <translation>Die Zeit der TimeStamped-Nachricht hat %1 Nanosekunden, mehr als eine Sekunde</translation>
    </message>
    <message>
        <source>JSON stamp&apos;s &quot;sample&quot; is empty: it names no sample</source>
        <translation>&quot;sample&quot; des JSON-Stempels ist leer: er benennt kein Sample</translation>
    </message>
    <message>
        <source>not CDR: the encapsulation header is %1</source>
        <translation>kein CDR: der Kapselungskopf ist %1</translation>
    </message>
    <message>
        <source>TimeStamped holds a time before 1970</source>
        <translation>TimeStamped enthält eine Zeit vor 1970</translation>
    </message>
</context>
<context>
    <name>StampTopicModel</name>
    <message>
        <source>%1  (%2)</source>
        <translation>%1  (%2)</translation>
    </message>
    <message>
        <source>%1: in the pipeline</source>
        <translation>%1: in der Pipeline</translation>
    </message>
    <message>
        <source>%1: not in the pipeline; drag it there or press Enter</source>
        <translation>%1: nicht in der Pipeline; dorthin ziehen oder Eingabe drücken</translation>
    </message>
    <message>
        <source>%1  (%2, %3 malformed)</source>
        <translation>%1  (%2, %3 fehlerhaft)</translation>
    </message>
    <message>
        <source>%1: %2 messages, none a stamp this tool reads (see the counts below the chart)</source>
        <translation>%1: %2 Nachrichten, keine davon ein lesbarer Stempel (siehe die Zähler unter dem Diagramm)</translation>
    </message>
</context>
<context>
    <name>SuiteCsv</name>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>empty file: expected a header row of stamp topics</source>
        <translation>leere Datei: eine Kopfzeile mit Zeitstempel-Topics erwartet</translation>
    </message>
    <message>
        <source>unterminated quote in the header row</source>
        <translation>nicht geschlossenes Anführungszeichen in der Kopfzeile</translation>
    </message>
    <message>
        <source>column %1 of the header row has no topic name</source>
        <translation>Spalte %1 der Kopfzeile hat keinen Topic-Namen</translation>
    </message>
    <message>
        <source>the first row holds times, not topic names: is the header row missing?</source>
        <translation>die erste Zeile enthält Zeiten, keine Topic-Namen: fehlt die Kopfzeile?</translation>
    </message>
    <message>
        <source>topic %1 appears twice in the header row</source>
        <translation>Topic %1 steht zweimal in der Kopfzeile</translation>
    </message>
    <message>
        <source>unterminated quote</source>
        <translation>nicht geschlossenes Anführungszeichen</translation>
    </message>
    <message>
        <source>%1 cells, the header has %2</source>
        <translation>%1 Zellen, die Kopfzeile hat %2</translation>
    </message>
    <message>
        <source>column %1 (%2): &quot;%3&quot; is not a time in seconds</source>
        <translation>Spalte %1 (%2): &quot;%3&quot; ist keine Zeit in Sekunden</translation>
    </message>
    <message>
        <source>column %1 of the header row holds a NUL byte</source>
        <translation>Spalte %1 der Kopfzeile enthält ein NUL-Byte</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>column %1 (%2): a NUL byte in the cell</source>
        <translation>Spalte %1 (%2): ein NUL-Byte in der Zelle</translation>
    </message>
    <message>
        <source>column %1 (%2): %3 is %4</source>
        <translation>Spalte %1 (%2): %3 ist %4</translation>
    </message>
    <message>
        <source>refused: reading it takes more than %1 s</source>
        <translation>abgelehnt: das Lesen dauert länger als %1 s</translation>
    </message>
    <message>
        <source>refused: a row of more than %1 MiB</source>
        <translation>abgelehnt: eine Zeile von mehr als %1 MiB</translation>
    </message>
    <message>
        <source>refused: it has more than %1 cells (the most a measurement file may have)</source>
        <translation>abgelehnt: sie hat mehr als %1 Zellen (das Höchste, was eine Messdatei haben darf)</translation>
    </message>
</context>
<context>
    <name>TimelineChart</name>
    <message>
        <source>total, mean per second</source>
        <translation>gesamt, Mittel je Sekunde</translation>
    </message>
    <message>
        <source>highest per second</source>
        <translation>Höchstwert je Sekunde</translation>
    </message>
    <message>
        <source>latency [ms]</source>
        <translation>Latenz [ms]</translation>
    </message>
    <message>
        <source>sample time</source>
        <translation>Probenzeit</translation>
    </message>
</context>
<context>
    <name>TopicNames</name>
    <message>
        <source>it contains U+FFFD, the mark of bytes that were not valid UTF-8</source>
        <translation>er enthält U+FFFD, das Zeichen für Bytes, die kein gültiges UTF-8 waren</translation>
    </message>
    <message>
        <source>it is not valid Unicode (half of a UTF-16 surrogate pair)</source>
        <translation>er ist kein gültiges Unicode (die Hälfte eines UTF-16-Surrogatpaars)</translation>
    </message>
    <message>
        <source>it is empty</source>
        <translation>er ist leer</translation>
    </message>
    <message>
        <source>it must start with a letter, &apos;/&apos; or &apos;~&apos;</source>
        <translation>er muss mit einem Buchstaben, &apos;/&apos; oder &apos;~&apos; beginnen</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not allowed (only letters, digits, &apos;_&apos; and &apos;/&apos;)</source>
        <translation>&apos;%1&apos; ist nicht erlaubt (nur Buchstaben, Ziffern, &apos;_&apos; und &apos;/&apos;)</translation>
    </message>
    <message>
        <source>it contains &apos;//&apos;</source>
        <translation>er enthält &apos;//&apos;</translation>
    </message>
    <message>
        <source>it ends with &apos;/&apos;</source>
        <translation>er endet auf &apos;/&apos;</translation>
    </message>
    <message>
        <source>&apos;~&apos; must be followed by &apos;/&apos;</source>
        <translation>auf &apos;~&apos; muss &apos;/&apos; folgen</translation>
    </message>
    <message>
        <source>in ROS 2 a name level must not start with a digit</source>
        <translation>in ROS 2 darf eine Namensebene nicht mit einer Ziffer beginnen</translation>
    </message>
    <message>
        <source>it contains a NUL character</source>
        <translation>er enthält ein NUL-Zeichen</translation>
    </message>
    <message>
        <source>it is longer than 65535 bytes</source>
        <translation>er ist länger als 65535 Bytes</translation>
    </message>
    <message>
        <source>wildcards are not allowed in a published topic</source>
        <translation>Platzhalter sind in einem veröffentlichten Topic nicht erlaubt</translation>
    </message>
    <message>
        <source>&apos;#&apos; must be a whole level and the last one</source>
        <translation>&apos;#&apos; muss eine ganze Ebene und die letzte sein</translation>
    </message>
    <message>
        <source>&apos;+&apos; must be a whole level</source>
        <translation>&apos;+&apos; muss eine ganze Ebene sein</translation>
    </message>
</context>
<context>
    <name>TopicTableModel</name>
    <message>
        <source>/s</source>
        <translation>/s</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>waiting…</source>
        <translation>warte …</translation>
    </message>
    <message>
        <source>Subscribe and show rate, bandwidth and the last message</source>
        <translation>Abonnieren und Rate, Bandbreite und letzte Nachricht zeigen</translation>
    </message>
    <message>
        <source>Monitor: subscribe and show rate, bandwidth and the last message</source>
        <translation>Beobachten: abonnieren und Rate, Bandbreite und letzte Nachricht zeigen</translation>
    </message>
    <message>
        <source>Mon</source>
        <translation>Beob.</translation>
    </message>
    <message>
        <source>Topic</source>
        <translation>Topic</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Typ</translation>
    </message>
    <message>
        <source>Pubs</source>
        <translation>Pubs</translation>
    </message>
    <message>
        <source>Subs</source>
        <translation>Subs</translation>
    </message>
    <message>
        <source>Rate (Hz)</source>
        <translation>Rate (Hz)</translation>
    </message>
    <message>
        <source>Bandwidth</source>
        <translation>Bandbreite</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>Größe</translation>
    </message>
    <message>
        <source>Last</source>
        <translation>Zuletzt</translation>
    </message>
    <message>
        <source>The last message came %1 s ago; the messages were %2 ms old when they came (median of the last %3, by their DDS source timestamps: the writer&apos;s clock).</source>
        <translation>Die letzte Nachricht kam vor %1 s; die Nachrichten waren beim Eintreffen %2 ms alt (Median der letzten %3, nach ihren DDS-Quellzeitstempeln: der Uhr des Schreibers).</translation>
    </message>
</context>
<context>
    <name>TopicTree</name>
    <message>
        <source>Namespace %1: drop MQTT topics here to bridge them below it</source>
        <translation>Namensraum %1: MQTT-Topics hier ablegen, um sie darunter zu überbrücken</translation>
    </message>
</context>
<context>
    <name>UdpClockProber</name>
    <message>
        <source>cannot open a UDP socket: %1</source>
        <translation>ein UDP-Socket lässt sich nicht öffnen: %1</translation>
    </message>
</context>
<context>
    <name>WaitingText</name>
    <message>
        <source>and %1 more</source>
        <translation>und %1 weitere</translation>
    </message>
    <message>
        <source>%1 topics under %2 (%3)</source>
        <translation>%1 Topics unter %2 (%3)</translation>
    </message>
    <message>
        <source>%1 topics (%2)</source>
        <translation>%1 Topics (%2)</translation>
    </message>
    <message>
        <source> from the broker %1 and the ROS master %2</source>
        <translation> vom Broker %1 und vom ROS-Master %2</translation>
    </message>
    <message>
        <source> from the broker %1</source>
        <translation> vom Broker %1</translation>
    </message>
    <message>
        <source> from the ROS master %1</source>
        <translation> vom ROS-Master %1</translation>
    </message>
    <message>
        <source> on %1</source>
        <translation> auf %1</translation>
    </message>
    <message>
        <source>nothing has arrived since %1 (%2 s): no %3 yet%4%5</source>
        <translation>seit %1 (%2 s) ist nichts angekommen: noch kein(e) %3%4%5</translation>
    </message>
</context>
<context>
    <name>WatchCommand</name>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1: not a bridge config: %2</source>
        <translation>%1: keine Bridge-Konfiguration: %2</translation>
    </message>
    <message>
        <source>Broker URL (default: the first config&apos;s broker).</source>
        <translation>Broker-URL (Vorgabe: der Broker der ersten Konfiguration).</translation>
    </message>
    <message>
        <source>ROS master URI (default $ROS_MASTER_URI).</source>
        <translation>ROS-Master-URI (Vorgabe $ROS_MASTER_URI).</translation>
    </message>
    <message>
        <source>Rules YAML: thresholds for all links and per link.</source>
        <translation>Regel-YAML: Schwellen für alle Verbindungen und je Verbindung.</translation>
    </message>
    <message>
        <source>Serve Prometheus metrics at http://HOST:PORT/metrics (e.g. 127.0.0.1:9464).</source>
        <translation>Prometheus-Metriken unter http://HOST:PORT/metrics bereitstellen (z. B. 127.0.0.1:9464).</translation>
    </message>
    <message>
        <source>Append every event to FILE as a JSON line.</source>
        <translation>Jedes Ereignis als JSON-Zeile an DATEI anhängen.</translation>
    </message>
    <message>
        <source>Stop after S seconds (default: at Ctrl+C).</source>
        <translation>Nach S Sekunden aufhören (Vorgabe: bei Strg+C).</translation>
    </message>
    <message>
        <source>mqtt_client configs whose mappings are watched.</source>
        <translation>mqtt_client-Konfigurationen, deren Mappings überwacht werden.</translation>
    </message>
    <message numerus="yes">
        <source>watching %n link(s) of %1; Ctrl+C stops</source>
        <translation>
            <numerusform>überwache %n Verbindung von %1; Strg+C beendet</numerusform>
            <numerusform>überwache %n Verbindungen von %1; Strg+C beendet</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 s: %2 ok, %3 warning, %4 alert</source>
        <translation>%1 s: %2 ok, %3 Warnung, %4 Alarm</translation>
    </message>
    <message>
        <source>Watched configs: %1</source>
        <translation>Überwachte Konfigurationen: %1</translation>
    </message>
    <message>
        <source>Record the events in this run file (never overwritten); bridgescope report lists them.</source>
        <translation>Die Ereignisse in dieser Laufdatei aufzeichnen (nie überschrieben); bridgescope report listet sie auf.</translation>
    </message>
    <message>
        <source>The run&apos;s name (default: the file&apos;s base name).</source>
        <translation>Name des Laufs (Standard: der Basisname der Datei).</translation>
    </message>
    <message>
        <source>Notes kept with the run.</source>
        <translation>Notizen, die mit dem Lauf gespeichert werden.</translation>
    </message>
    <message>
        <source>--name and --notes describe a run: give -o RUN.bsrun too</source>
        <translation>--name und --notes beschreiben einen Lauf: bitte auch -o RUN.bsrun angeben</translation>
    </message>
    <message>
        <source>recording stopped: %1</source>
        <translation>Aufnahme beendet: %1</translation>
    </message>
    <message>
        <source>events recorded in %1</source>
        <translation>Ereignisse aufgezeichnet in %1</translation>
    </message>
    <message>
        <source>Watch only the configs&apos; mappings, not the links mqtt_client announces on the broker.</source>
        <translation>Nur die Abbildungen der Konfigurationen beobachten, nicht die Verbindungen, die mqtt_client am Broker ankündigt.</translation>
    </message>
    <message>
        <source>The timestamp topics&apos; pipeline: a mapping with a timestamp_topic_prefix takes its latency from PREFIX/in to PREFIX/out, and -o records the samples as well.</source>
        <translation>Die Pipeline der Zeitstempel-Topics: Eine Abbildung mit timestamp_topic_prefix erhält ihre Latenz von PREFIX/in bis PREFIX/out, und -o zeichnet auch die Messpunkte auf.</translation>
    </message>
    <message>
        <source>watch needs a bridge config, or --broker to watch the links announced there; see bridgescope watch --help</source>
        <translation>watch braucht eine Bridge-Konfiguration oder --broker, um die dort angekündigten Verbindungen zu beobachten; siehe bridgescope watch --help</translation>
    </message>
    <message>
        <source>MQTT message</source>
        <translation>MQTT-Nachricht</translation>
    </message>
    <message>
        <source>; %1 payloads evicted from the topic history (budget %2 MiB)</source>
        <translation>; %1 Nutzdaten aus dem Topic-Verlauf verdrängt (Budget %2 MiB)</translation>
    </message>
    <message>
        <source>; %1 metrics clients dropped</source>
        <translation>; %1 Metrik-Clients getrennt</translation>
    </message>
    <message>
        <source>; %1 messages on topics not tracked (budget %2 topics, %3 MiB of names)</source>
        <translation>; %1 Nachrichten auf nicht erfassten Topics (Budget %2 Topics, %3 MiB Namen)</translation>
    </message>
    <message>
        <source>; %1 announced links not watched (cap %2)</source>
        <translation>; %1 angekündigte Links nicht beobachtet (Obergrenze %2)</translation>
    </message>
    <message>
        <source>metrics at http://%1:%2/metrics</source>
        <translation>Metriken unter http://%1:%2/metrics</translation>
    </message>
    <message>
        <source>, %1 unknown (the watch&apos;s own connection is down)</source>
        <translation>, %1 unbekannt (die eigene Verbindung der Beobachtung ist unterbrochen)</translation>
    </message>
    <message>
        <source>Exit 0 even when nothing was heard (neither the broker nor the master reached, nobody on the ROS 2 domain).</source>
        <translation>Status 0 auch dann, wenn nichts zu hören war (weder Broker noch Master erreichbar, niemand in der ROS-2-Domäne).</translation>
    </message>
    <message>
        <source>nothing was watched: %1; --allow-empty accepts that</source>
        <translation>nichts wurde beobachtet: %1; --allow-empty lässt das zu</translation>
    </message>
    <message>
        <source>Watches every mapping of the configs as a link, until Ctrl+C: rate at both ends, messages lost, Header.seq gaps, stalls, the source stopping, latency of stamped messages and the bridges&apos; state; and, from their MQTT end, the links mqtt_client announces on the broker that no config maps. Every change of a link&apos;s state is an event, printed as a JSON line.
A broker or master that cannot be reached is said within 5 s; it keeps trying.
Exit status: 0 stopped, 1 nothing heard: no broker, no master, nobody on ROS 2 (without --allow-empty), the metrics port was not served or the run file not written, 2 bad options.</source>
        <translation>Beobachtet jede Abbildung der Konfigurationen als Verbindung, bis Strg+C: Rate an beiden Enden, verlorene Nachrichten, Lücken in Header.seq, Stillstände, eine verstummte Quelle, Latenz gestempelter Nachrichten und den Zustand der Bridges; dazu, von ihrem MQTT-Ende aus, die Verbindungen, die mqtt_client am Broker ankündigt und keine Konfiguration abbildet. Jede Zustandsänderung einer Verbindung ist ein Ereignis und wird als JSON-Zeile ausgegeben.
Ein nicht erreichbarer Broker oder Master wird innerhalb von 5 s gemeldet; es wird weiter versucht.
Exit-Status: 0 beendet, 1 nichts zu hören: kein Broker, kein Master, niemand auf ROS 2 (ohne --allow-empty), der Metrik-Port wurde nicht bedient oder die Messlauf-Datei nicht geschrieben, 2 falsche Optionen.</translation>
    </message>
    <message>
        <source>; %1 messages not timed (more between two reads than the watch keeps)</source>
        <translation>; %1 Nachrichten nicht zeitlich erfasst (mehr zwischen zwei Lesevorgängen, als die Beobachtung behält)</translation>
    </message>
    <message>
        <source>A label on every metric, e.g. site=garage or host=vehicle-3 (default host: this machine&apos;s name); repeat it for more.</source>
        <translation>Ein Label an jeder Metrik, z. B. site=garage oder host=vehicle-3 (Vorgabe für host: der Name dieses Rechners); für mehr wiederholen.</translation>
    </message>
    <message>
        <source>--label names the metrics: give --metrics HOST:PORT too</source>
        <translation>--label benennt die Metriken: auch --metrics HOST:PORT angeben</translation>
    </message>
    <message>
        <source>at most %1 --label options</source>
        <translation>höchstens %1 Optionen --label</translation>
    </message>
    <message numerus="yes">
        <source>%n event line(s) held back by the storm bound (%1 a second after a burst of %2): counted in the held_back lines</source>
        <translation>
            <numerusform>%n Ereigniszeile von der Sturmgrenze zurückgehalten (%1 pro Sekunde nach einem Schub von %2): in den held_back-Zeilen gezählt</numerusform>
            <numerusform>%n Ereigniszeilen von der Sturmgrenze zurückgehalten (%1 pro Sekunde nach einem Schub von %2): in den held_back-Zeilen gezählt</numerusform>
        </translation>
    </message>
    <message>
        <source>; ROS publishers asked again for %1 topics (the master listed them, none connected), %2 subscribed again, %3 silent now</source>
        <translation>; ROS-Publisher für %1 Topics erneut angefragt (der Master nannte sie, keiner verband sich), %2 neu abonniert, %3 jetzt stumm</translation>
    </message>
    <message>
        <source>watch ended after %1 s: links %2 (%3 ok, %4 warning, %5 alert, %6 unknown), events %7 (%8 alerts), messages %9 at the sources and %10 at the destinations, lost %11 by the counts and %13 by content, stalls %12</source>
        <translation>Beobachtung nach %1 s beendet: Verbindungen %2 (%3 ok, %4 Warnung, %5 Alarm, %6 unbekannt), Ereignisse %7 (%8 Alarme), Nachrichten %9 an den Quellen und %10 an den Zielen, verloren %11 nach den Zählungen und %13 nach dem Inhalt, Stillstände %12</translation>
    </message>
</context>
<context>
    <name>WatchMetrics</name>
    <message>
        <source>label &apos;%1&apos; is not NAME=VALUE</source>
        <translation>Label „%1“ hat nicht die Form NAME=WERT</translation>
    </message>
    <message>
        <source>label name &apos;%1&apos; is not a Prometheus label name (letters, digits and _, not starting with a digit or __, at most 64)</source>
        <translation>Labelname „%1“ ist kein Prometheus-Labelname (Buchstaben, Ziffern und _, nicht mit einer Ziffer oder __ beginnend, höchstens 64)</translation>
    </message>
    <message>
        <source>label &apos;%1&apos; is one the watch writes itself</source>
        <translation>Label „%1“ schreibt die Überwachung selbst</translation>
    </message>
    <message>
        <source>label &apos;%1&apos; is one Prometheus sets when it scrapes; name the host with host=</source>
        <translation>Label „%1“ setzt Prometheus beim Abfragen; den Rechner mit host= benennen</translation>
    </message>
    <message>
        <source>label &apos;%1&apos; has no value (Prometheus drops an empty label)</source>
        <translation>Label „%1“ hat keinen Wert (Prometheus verwirft ein leeres Label)</translation>
    </message>
    <message>
        <source>label &apos;%1&apos; is longer than %2 bytes</source>
        <translation>Label „%1“ ist länger als %2 Bytes</translation>
    </message>
    <message>
        <source>at most %1 labels of a watch&apos;s own</source>
        <translation>höchstens %1 eigene Labels einer Überwachung</translation>
    </message>
</context>
<context>
    <name>WatchRules</name>
    <message>
        <source>rules are a mapping with defaults and links</source>
        <translation>Regeln sind eine Zuordnung mit defaults und links</translation>
    </message>
    <message>
        <source>%1 takes warning and alert levels, each a number ≥ 0</source>
        <translation>%1 erwartet Warn- und Alarmstufe, jeweils eine Zahl ≥ 0</translation>
    </message>
    <message>
        <source>%1 takes a number ≥ 0 or {warning: N, alert: N}</source>
        <translation>%1 erwartet eine Zahl ≥ 0 oder {warning: N, alert: N}</translation>
    </message>
    <message>
        <source>unknown setting &apos;%1&apos; (known: %2)</source>
        <translation>unbekannte Einstellung &apos;%1&apos; (bekannt: %2)</translation>
    </message>
    <message>
        <source>defaults is a mapping of settings</source>
        <translation>defaults ist eine Zuordnung von Einstellungen</translation>
    </message>
    <message>
        <source>links is a list of {match: PATTERN, settings...}</source>
        <translation>links ist eine Liste von {match: MUSTER, Einstellungen...}</translation>
    </message>
    <message>
        <source>%1 entries in links; at most %2 are read (merge patterns with * and ?)</source>
        <translation>%1 Einträge in links; höchstens %2 werden gelesen (Muster mit * und ? zusammenfassen)</translation>
    </message>
    <message>
        <source>every entry of links needs a match pattern</source>
        <translation>jeder Eintrag von links braucht ein match-Muster</translation>
    </message>
    <message>
        <source>a match pattern of %1 characters; at most %2</source>
        <translation>ein Suchmuster mit %1 Zeichen; höchstens %2</translation>
    </message>
</context>
<context>
    <name>WatchSession</name>
    <message>
        <source>%1 links would be watched; the limit is %2 links per window: nothing was subscribed</source>
        <translation>%1 Verbindungen würden beobachtet; die Grenze ist %2 Verbindungen je Fenster: nichts wurde abonniert</translation>
    </message>
</context>
<context>
    <name>YamlLimits</name>
    <message>
        <source>The alias *%1 refers to a node that contains it; the document would be infinite.</source>
        <translation>Der Alias *%1 verweist auf einen Knoten, der ihn enthält; das Dokument wäre unendlich.</translation>
    </message>
    <message>
        <source>Remove the alias or point it at a node outside its anchor.</source>
        <translation>Entfernen Sie den Alias oder lassen Sie ihn auf einen Knoten außerhalb seines Ankers verweisen.</translation>
    </message>
    <message>
        <source>The alias *%1 makes aliases repeat %2 nodes; at most %3 are read.</source>
        <translation>Mit dem Alias *%1 wiederholen Aliase %2 Knoten; höchstens %3 werden gelesen.</translation>
    </message>
    <message>
        <source>The alias *%1 makes aliases repeat %2 bytes of text; at most %3 are read.</source>
        <translation>Mit dem Alias *%1 wiederholen Aliase %2 Bytes Text; höchstens %3 werden gelesen.</translation>
    </message>
    <message>
        <source>The alias *%1 nests collections %2 deep; at most %3 are read.</source>
        <translation>Der Alias *%1 verschachtelt Listen und Maps %2 tief; höchstens %3 werden gelesen.</translation>
    </message>
    <message>
        <source>Anchors and aliases are for sharing a few values; write the values out instead.</source>
        <translation>Anker und Aliase dienen dazu, wenige Werte zu teilen; schreiben Sie die Werte stattdessen aus.</translation>
    </message>
    <message>
        <source>The document has more than %1 nodes (values, keys, lists and maps); at most %1 are read.</source>
        <translation>Das Dokument hat mehr als %1 Knoten (Werte, Schlüssel, Listen und Maps); höchstens %1 werden gelesen.</translation>
    </message>
    <message>
        <source>Split the file.</source>
        <translation>Teilen Sie die Datei auf.</translation>
    </message>
    <message>
        <source>Lists and maps are nested more than %1 deep here; at most %1 are read.</source>
        <translation>Listen und Maps sind hier mehr als %1 tief verschachtelt; höchstens %1 werden gelesen.</translation>
    </message>
    <message>
        <source>Flatten the structure.</source>
        <translation>Verschachteln Sie weniger tief.</translation>
    </message>
    <message>
        <source>Byte 0x%1 is not valid UTF-8; the file must be UTF-8 text.</source>
        <translation>Das Byte 0x%1 ist kein gültiges UTF-8; die Datei muss UTF-8-Text sein.</translation>
    </message>
    <message>
        <source>Save the file as UTF-8, or correct the text at this place.</source>
        <translation>Speichern Sie die Datei als UTF-8 oder korrigieren Sie den Text an dieser Stelle.</translation>
    </message>
    <message>
        <source>The key &quot;%1&quot; appears twice in this mapping (first on line %2); YAML forbids it, and readers disagree on which value counts.</source>
        <translation>Der Schlüssel &quot;%1&quot; kommt in dieser Abbildung zweimal vor (zuerst in Zeile %2); YAML verbietet das, und Leser sind uneins, welcher Wert gilt.</translation>
    </message>
    <message>
        <source>~ (null, also written null, NULL or nothing)</source>
        <translation>~ (null, auch null, NULL oder leer geschrieben)</translation>
    </message>
    <message>
        <source>Remove one of the two, or rename it.</source>
        <translation>Entfernen Sie einen der beiden oder benennen Sie ihn um.</translation>
    </message>
    <message>
        <source>A carriage return without a line feed: yaml-cpp does not read it as a line break, but as part of the value.</source>
        <translation>Ein Wagenrücklauf ohne Zeilenvorschub: yaml-cpp liest ihn nicht als Zeilenumbruch, sondern als Teil des Werts.</translation>
    </message>
    <message>
        <source>Save the file with LF or CRLF line endings.</source>
        <translation>Speichern Sie die Datei mit LF- oder CRLF-Zeilenenden.</translation>
    </message>
    <message>
        <source>The control character U+%1 is not allowed in YAML; write it as an escape (\x%2) in a double-quoted string.</source>
        <translation>Das Steuerzeichen U+%1 ist in YAML nicht erlaubt; schreiben Sie es als Escape (\x%2) in einer Zeichenkette in doppelten Anführungszeichen.</translation>
    </message>
    <message>
        <source>Remove the character, or correct the text at this place.</source>
        <translation>Entfernen Sie das Zeichen oder korrigieren Sie den Text an dieser Stelle.</translation>
    </message>
    <message>
        <source>A list or a map is used as a key here; keys must be plain text.</source>
        <translation>Hier ist eine Liste oder eine Abbildung als Schlüssel verwendet; Schlüssel müssen einfacher Text sein.</translation>
    </message>
    <message>
        <source>Write the key as text, or remove the entry.</source>
        <translation>Schreiben Sie den Schlüssel als Text, oder entfernen Sie den Eintrag.</translation>
    </message>
    <message>
        <source>The file is larger than %1, the limit.</source>
        <translation>Die Datei ist größer als die Grenze von %1.</translation>
    </message>
    <message>
        <source>The file is %1, the limit is %2.</source>
        <translation>Die Datei ist %1 groß, die Grenze ist %2.</translation>
    </message>
</context>
<context>
    <name>YamlPreview</name>
    <message>
        <source>mqtt_client, ROS 1</source>
        <translation>mqtt_client, ROS 1</translation>
    </message>
    <message>
        <source>mqtt_client, ROS 2</source>
        <translation>mqtt_client, ROS 2</translation>
    </message>
    <message>
        <source>mqtt_bridge</source>
        <translation>mqtt_bridge</translation>
    </message>
    <message>
        <source>&amp;Layout:</source>
        <translation>&amp;Layout:</translation>
    </message>
    <message>
        <source>Saving edits the file in place: comments and formatting are kept.</source>
        <translation>Beim Speichern wird die Datei an Ort und Stelle geändert: Kommentare und Formatierung bleiben erhalten.</translation>
    </message>
    <message>
        <source>Saving in this layout writes the file anew: its comments are not kept.</source>
        <translation>In diesem Layout wird die Datei neu geschrieben: Ihre Kommentare gehen verloren.</translation>
    </message>
    <message>
        <source>Read-only: this file cannot be edited or saved here, because it is not a bridge config Bridgescope can read. Fix it in a text editor and open it again.</source>
        <translation>Schreibgeschützt: Diese Datei kann hier weder bearbeitet noch gespeichert werden, weil sie keine Bridge-Konfiguration ist, die Bridgescope lesen kann. Korrigieren Sie sie in einem Texteditor und öffnen Sie sie erneut.</translation>
    </message>
    <message>
        <source>Line %1, column %2: %3</source>
        <translation>Zeile %1, Spalte %2: %3</translation>
    </message>
    <message>
        <source>Only the first %1 of %2 are shown.</source>
        <translation>Nur die ersten %1 von %2 werden gezeigt.</translation>
    </message>
    <message>
        <source>Line %1 is past the part shown.</source>
        <translation>Zeile %1 liegt hinter dem gezeigten Teil.</translation>
    </message>
</context>
<context>
    <name>YamlReader</name>
    <message>
        <source>unknown key &apos;%1&apos; (known: %2)</source>
        <translation>unbekannter Schlüssel &apos;%1&apos; (bekannt: %2)</translation>
    </message>
</context>
</TS>

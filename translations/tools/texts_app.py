"""Translations of the command-line tools (app/cli, app/robot-sim): source text -> (German,
Chinese). Option names, commands and file placeholders (FILE, DIR, N) stay as they are; the CLI's
table headings are kept as short as the English so the columns stay aligned."""

USAGE_EN = (
    "Usage:\n"
    "  learnid-cli scenario --print\n"
    "      Print the default scenario (the paper scenario) as JSON.\n"
    "  learnid-cli run [--scenario FILE] [--estimator paper|improved] [--iterations N]\n"
    "                  [--report FILE] [--export FILE] [--trial-csv DIR] [--apply]\n"
    "                  [--workspace DIR] [--quiet]\n"
    "      Run a commissioning session on the simulated robot. The table goes to\n"
    "      stdout, progress to stderr. Relative output paths are taken from\n"
    "      --workspace (default: the current directory). Files are written only\n"
    "      when every trial completed.\n"
    "      --robot can --can-plugin P --can-interface I [--nodes 1,2] [--can-log DIR]\n"
    "      runs it on CiA 402 drives on a CAN bus instead (docs/can-protocol.md);\n"
    "      --can-log writes every trial's frames as a candump log into DIR;\n"
    "      --can-sync-timeout MS stops a trial when no SYNC comes for MS (default 20).\n"
    "  learnid-cli replay --candump FILE [--candump FILE2 ...] [--scenario FILE]\n"
    "                     [--estimator paper|improved] [--nodes 1,2] [--report FILE]\n"
    "                     [--export FILE] [--trial-csv DIR] [--workspace DIR] [--quiet]\n"
    "      Re-identify from recorded trials: the session runs again with each log\n"
    "      (one per trial, in order) answering in place of the robot.\n"
    "  learnid-cli COMMAND --help\n"
    "      The options of one command.\n")
USAGE_DE = (
    "Aufruf:\n"
    "  learnid-cli scenario --print\n"
    "      Gibt das Standardszenario (das Szenario des Artikels) als JSON aus.\n"
    "  learnid-cli run [--scenario FILE] [--estimator paper|improved] [--iterations N]\n"
    "                  [--report FILE] [--export FILE] [--trial-csv DIR] [--apply]\n"
    "                  [--workspace DIR] [--quiet]\n"
    "      Führt eine Inbetriebnahmesitzung am simulierten Roboter aus. Tabelle nach\n"
    "      stdout, Fortschritt nach stderr. Relative Ausgabepfade gelten ab\n"
    "      --workspace (Standard: aktuelles Verzeichnis). Dateien werden nur\n"
    "      geschrieben, wenn jeder Versuch abgeschlossen wurde.\n"
    "      --robot can --can-plugin P --can-interface I [--nodes 1,2] [--can-log DIR]\n"
    "      führt sie stattdessen an CiA-402-Antrieben am CAN-Bus aus (docs/can-protocol.md);\n"
    "      --can-log schreibt die Frames jedes Versuchs als candump-Log nach DIR;\n"
    "      --can-sync-timeout MS beendet einen Versuch, wenn MS lang kein SYNC kommt (Standard 20).\n"
    "  learnid-cli replay --candump FILE [--candump FILE2 ...] [--scenario FILE]\n"
    "                     [--estimator paper|improved] [--nodes 1,2] [--report FILE]\n"
    "                     [--export FILE] [--trial-csv DIR] [--workspace DIR] [--quiet]\n"
    "      Identifiziert neu aus aufgezeichneten Versuchen: die Sitzung läuft erneut,\n"
    "      und jedes Log (eines pro Versuch, der Reihe nach) antwortet statt des Roboters.\n"
    "  learnid-cli COMMAND --help\n"
    "      Die Optionen eines Befehls.\n")
USAGE_ZH = (
    "用法：\n"
    "  learnid-cli scenario --print\n"
    "      以 JSON 格式输出默认场景（论文场景）。\n"
    "  learnid-cli run [--scenario FILE] [--estimator paper|improved] [--iterations N]\n"
    "                  [--report FILE] [--export FILE] [--trial-csv DIR] [--apply]\n"
    "                  [--workspace DIR] [--quiet]\n"
    "      在仿真机器人上运行一次调试会话。表格输出到 stdout，\n"
    "      进度输出到 stderr。相对输出路径以 --workspace 为基准\n"
    "      （默认：当前目录）。只有当所有试验都完成时\n"
    "      才写入文件。\n"
    "      --robot can --can-plugin P --can-interface I [--nodes 1,2] [--can-log DIR]\n"
    "      改为在 CAN 总线上的 CiA 402 驱动器上运行（docs/can-protocol.md）；\n"
    "      --can-log 将每次试验的帧以 candump 日志写入 DIR；\n"
    "      --can-sync-timeout MS：MS 内无 SYNC 即停止试验（默认 20）。\n"
    "  learnid-cli replay --candump FILE [--candump FILE2 ...] [--scenario FILE]\n"
    "                     [--estimator paper|improved] [--nodes 1,2] [--report FILE]\n"
    "                     [--export FILE] [--trial-csv DIR] [--workspace DIR] [--quiet]\n"
    "      根据记录的试验重新辨识：会话再次运行，由每个日志\n"
    "      （每次试验一个，按顺序）代替机器人应答。\n"
    "  learnid-cli COMMAND --help\n"
    "      某个命令的选项。\n")

T = {
 USAGE_EN: (USAGE_DE, USAGE_ZH),
 # learnid-cli
 'learnid-cli: error: %1': ('learnid-cli: Fehler: %1', 'learnid-cli：错误：%1'),
 "--robot: must be 'sim' or 'can', got '%1'": ("--robot: muss 'sim' oder 'can' sein, gefunden: '%1'", "--robot：必须是 'sim' 或 'can'，实际为 '%1'"),
 '--%1 needs --robot can': ('--%1 braucht --robot can', '--%1 需要 --robot can'),
 "--can-sync-timeout: must be a whole number of ms from 1 to 60000, got '%1'":
   ("--can-sync-timeout: muss eine ganze Zahl von ms von 1 bis 60000 sein, gefunden: '%1'",
    "--can-sync-timeout：必须是 1 到 60000 之间的整数毫秒，实际为 '%1'"),
 'Longest SYNC gap in a trial [ms].': ('Längste SYNC-Lücke in einem Versuch [ms].', '试验中最长的 SYNC 间隔 [ms]。'),
 '--robot can needs --can-plugin (e.g. socketcan, virtualcan)':
   ('--robot can braucht --can-plugin (z. B. socketcan, virtualcan)', '--robot can 需要 --can-plugin（例如 socketcan、virtualcan）'),
 '--robot can needs --can-interface (e.g. can0)': ('--robot can braucht --can-interface (z. B. can0)', '--robot can 需要 --can-interface（例如 can0）'),
 "--nodes: %1 in '%2'": ("--nodes: %1 in '%2'", "--nodes：'%2' 中 %1"),
 '--nodes %1: %2': ('--nodes %1: %2', '--nodes %1：%2'),
 '--robot %1: %2': ('--robot %1: %2', '--robot %1：%2'),
 'Print the default scenario.': ('Standardszenario ausgeben.', '输出默认场景。'),
 'Scenario file (JSON, docs/scenario.md); default: the paper scenario.':
   ('Szenariodatei (JSON, docs/scenario.md); Standard: das Szenario des Artikels.', '场景文件（JSON，docs/scenario.md）；默认：论文场景。'),
 'Learning law: paper or improved.': ('Lerngesetz: paper oder improved.', '学习律：paper 或 improved。'),
 'Learning trials, 1 to 100.': ('Lernversuche, 1 bis 100.', '学习试验次数，1 到 100。'),
 'Write the session report (JSON) to FILE.': ('Den Sitzungsbericht (JSON) nach FILE schreiben.', '将会话报告（JSON）写入 FILE。'),
 'Write the parameter file (JSON and DCF) to FILE.': ('Die Parameterdatei (JSON und DCF) nach FILE schreiben.', '将参数文件（JSON 和 DCF）写入 FILE。'),
 "Write each trial's samples as CSV into DIR.": ('Die Abtastwerte jedes Versuchs als CSV nach DIR schreiben.', '将每次试验的采样以 CSV 写入 DIR。'),
 'Accept and apply the final estimate to the robot.': ('Die letzte Schätzung übernehmen und auf den Roboter übertragen.', '接受最终估计并写入机器人。'),
 'Folder that relative output paths are taken from; default: the current directory.':
   ('Ordner, ab dem relative Ausgabepfade gelten; Standard: das aktuelle Verzeichnis.', '相对输出路径的基准文件夹；默认：当前目录。'),
 'No progress lines on stderr.': ('Keine Fortschrittszeilen auf stderr.', '不在 stderr 上输出进度行。'),
 'sim (default) or can.': ('sim (Standard) oder can.', 'sim（默认）或 can。'),
 'CAN interface, e.g. can0.': ('CAN-Schnittstelle, z. B. can0.', 'CAN 接口，例如 can0。'),
 "CANopen node id of each joint's drive, e.g. 1,2.": ('CANopen-Knotennummer des Antriebs jedes Gelenks, z. B. 1,2.', '每个关节驱动器的 CANopen 节点号，例如 1,2。'),
 "Write each trial's CAN frames as a candump log into DIR.": ('Die CAN-Frames jedes Versuchs als candump-Log nach DIR schreiben.', '将每次试验的 CAN 帧以 candump 日志写入 DIR。'),
 'A recorded trial (candump log); once per trial, in order.': ('Ein aufgezeichneter Versuch (candump-Log); einmal pro Versuch, der Reihe nach.', '一次记录的试验（candump 日志）；每次试验一个，按顺序。'),
 "Show this command's options.": ('Die Optionen dieses Befehls anzeigen.', '显示此命令的选项。'),
 'Print the default scenario as JSON.': ('Das Standardszenario als JSON ausgeben.', '以 JSON 格式输出默认场景。'),
 'Re-identify from recorded trials: the session runs again with each log\nanswering in place of the robot.':
   ('Neu identifizieren aus aufgezeichneten Versuchen: die Sitzung läuft erneut,\nund jedes Log antwortet statt des Roboters.', '根据记录的试验重新辨识：会话再次运行，\n由每个日志代替机器人应答。'),
 'Run a commissioning session on the simulated robot, or with --robot can\non CiA 402 drives on a CAN bus (docs/can-protocol.md).':
   ('Eine Inbetriebnahmesitzung am simulierten Roboter ausführen, oder mit --robot can\nan CiA-402-Antrieben am CAN-Bus (docs/can-protocol.md).', '在仿真机器人上运行调试会话，或使用 --robot can\n在 CAN 总线上的 CiA 402 驱动器上运行（docs/can-protocol.md）。'),
 'Usage: learnid-cli %1 [options]\n\n%2\n\n%3': ('Aufruf: learnid-cli %1 [Optionen]\n\n%2\n\n%3', '用法：learnid-cli %1 [选项]\n\n%2\n\n%3'),
 'trial %1: %2, T = %3 s, no samples recorded': ('Versuch %1: %2, T = %3 s, keine Abtastwerte aufgezeichnet', '试验 %1：%2，T = %3 s，未记录采样'),
 "'scenario' needs --print": ("'scenario' braucht --print", "'scenario' 需要 --print"),
 'no command given': ('kein Befehl angegeben', '未给出命令'),
 "unknown command '%1'": ("unbekannter Befehl '%1'", "未知命令 '%1'"),
 "unexpected argument '%1'": ("unerwartetes Argument '%1'", "意外的参数 '%1'"),
 "--iterations: must be a whole number from 1 to 100, got '%1'":
   ("--iterations: muss eine ganze Zahl von 1 bis 100 sein, gefunden: '%1'", "--iterations：必须是 1 到 100 之间的整数，实际为 '%1'"),
 "'replay' needs at least one --candump FILE": ("'replay' braucht mindestens ein --candump FILE", "'replay' 至少需要一个 --candump FILE"),
 '--iterations: %1 trials need %1 logs, %2 given': ('--iterations: %1 Versuche brauchen %1 Logs, %2 angegeben', '--iterations：%1 次试验需要 %1 个日志，给出了 %2 个'),
 'trial': ('Vers.', '试验'),
 'change %': ('Änd. %', '变化 %'),
 'max|e|%1 deg': ('max|e|%1 °', '最大|e|%1 度'),
 'T s': ('T s', 'T s'),
 'cond': ('cond', 'cond'),
 'vs truth %': ('vs. wahr %', '相对真值 %'),
 '(rank %1: unobservable kept)': ('(Rang %1: nicht beobachtbare beibehalten)', '（秩 %1：保留不可观测参数）'),
 'trial %1: %2': ('Versuch %1: %2', '试验 %1：%2'),
 'trial %1: %2, T = %3 s, %4 samples, max tracking error %5 deg':
   ('Versuch %1: %2, T = %3 s, %4 Abtastwerte, max. Folgefehler %5°', '试验 %1：%2，T = %3 s，%4 个采样点，最大跟踪误差 %5 度'),
 "--estimator: unknown law '%1' (known: %2)": ("--estimator: unbekanntes Gesetz '%1' (bekannt: %2)", "--estimator：未知学习律 '%1'（已知：%2）"),
 'learnid-cli: %1, law %2, %3 learning trials': ('learnid-cli: %1, Gesetz %2, %3 Lernversuche', 'learnid-cli：%1，学习律 %2，%3 次学习试验'),
 'learnid-cli: no files written': ('learnid-cli: keine Dateien geschrieben', 'learnid-cli：未写入文件'),
 'learnid-cli: error: apply failed: %1': ('learnid-cli: Fehler: Übertragen fehlgeschlagen: %1', 'learnid-cli：错误：写入失败：%1'),
 'learnid-cli: estimate %1 applied to the robot': ('learnid-cli: Schätzung %1 auf den Roboter übertragen', 'learnid-cli：估计 %1 已写入机器人'),
 '--trial-csv: cannot create the folder %1': ('--trial-csv: Ordner %1 kann nicht angelegt werden', '--trial-csv：无法创建文件夹 %1'),
 'learnid-cli: wrote %1': ('learnid-cli: %1 geschrieben', 'learnid-cli：已写入 %1'),
 # learnid-robot-sim
 'SIGINT': ('SIGINT', 'SIGINT'),
 'SIGTERM': ('SIGTERM', 'SIGTERM'),
 'stdin closed': ('stdin geschlossen', 'stdin 已关闭'),
 'learnid-robot-sim: error: %1': ('learnid-robot-sim: Fehler: %1', 'learnid-robot-sim：错误：%1'),
 "Try 'learnid-robot-sim --help' for the options.": ("Die Optionen zeigt 'learnid-robot-sim --help'.", "选项请见 'learnid-robot-sim --help'。"),
 "--nodes: '%1' is not a CANopen node id (1 to 127) in '%2'":
   ("--nodes: '%1' ist keine CANopen-Knoten-ID (1 bis 127) in '%2'", "--nodes：'%2' 中的 '%1' 不是 CANopen 节点 ID（1 到 127）"),
 "--nodes: node %1 is listed twice in '%2'": ("--nodes: Knoten %1 ist in '%2' zweimal aufgeführt", "--nodes：节点 %1 在 '%2' 中被列出两次"),
 "--refuse-sdo: '%1' is not an object address INDEX:SUB such as 0x2200:1 (index in hex, sub-index 0 to 255)":
   ("--refuse-sdo: '%1' ist keine Objektadresse INDEX:SUB wie 0x2200:1 (Index hexadezimal, Subindex 0 bis 255)",
    "--refuse-sdo：'%1' 不是形如 0x2200:1 的对象地址 INDEX:SUB（索引为十六进制，子索引 0 到 255）"),
 "--%1: '%2' is not a whole number of at least %3": ("--%1: '%2' ist keine ganze Zahl von mindestens %3", "--%1：'%2' 不是不小于 %3 的整数"),
 'The robot on a CAN bus: one simulated CiA 402 drive per joint, the SYNC producer and the scenario\'s simulated arm. Prints "ready" once connected; runs until SIGINT, SIGTERM or stdin closes.':
   ('Der Roboter an einem CAN-Bus: ein simulierter CiA-402-Antrieb pro Gelenk, der SYNC-Erzeuger und der simulierte Arm des Szenarios. Gibt „ready“ aus, sobald verbunden; läuft bis SIGINT, SIGTERM oder bis stdin geschlossen wird.',
    'CAN 总线上的机器人：每个关节一个仿真 CiA 402 驱动器、SYNC 生产者以及场景的仿真机械臂。连接后输出“ready”；运行直到收到 SIGINT、SIGTERM 或 stdin 关闭。'),
 'Show this help.': ('Diese Hilfe anzeigen.', '显示此帮助。'),
 'Show the version.': ('Die Version anzeigen.', '显示版本。'),
 'QCanBus plugin, e.g. socketcan or virtualcan.': ('QCanBus-Plugin, z. B. socketcan oder virtualcan.', 'QCanBus 插件，例如 socketcan 或 virtualcan。'),
 'plugin': ('Plugin', '插件'),
 'CAN interface, e.g. can0 or tcp://127.0.0.1:35468/can0.':
   ('CAN-Schnittstelle, z. B. can0 oder tcp://127.0.0.1:35468/can0.', 'CAN 接口，例如 can0 或 tcp://127.0.0.1:35468/can0。'),
 'interface': ('Schnittstelle', '接口'),
 'Node ids of joint 1, 2, ... (default 1,2).': ('Knoten-IDs von Gelenk 1, 2, ... (Standard 1,2).', '关节 1、2……的节点 ID（默认 1,2）。'),
 'ids': ('IDs', 'ID'),
 'Scenario file (default: the paper scenario).': ('Szenariodatei (Standard: das Szenario des Artikels).', '场景文件（默认：论文场景）。'),
 'file': ('Datei', '文件'),
 "JSON file of the nodes' stored parameters, written at start and after every store.":
   ('JSON-Datei der gespeicherten Parameter der Knoten, geschrieben beim Start und nach jedem Speichern.',
    '节点已存储参数的 JSON 文件，在启动时及每次存储后写入。'),
 'Fault: lose this fraction (0 to 1) of the TPDOs.': ('Fehler: diesen Anteil (0 bis 1) der TPDOs verlieren.', '故障：丢失此比例（0 到 1）的 TPDO。'),
 'F': ('F', 'F'),
 'Fault: send nothing at all after N frames.': ('Fehler: nach N Frames gar nichts mehr senden.', '故障：N 帧之后完全停止发送。'),
 'N': ('N', 'N'),
 'Fault: the first node faults with EMCY 0x8611 at the K-th SYNC in Operation enabled.':
   ('Fehler: der erste Knoten geht beim K-ten SYNC in Betrieb freigegeben mit EMCY 0x8611 in Fehler.',
    '故障：第一个节点在运行使能状态下的第 K 个 SYNC 时以 EMCY 0x8611 报故障。'),
 'K': ('K', 'K'),
 'Fault: SDO writes to this object abort with 0x08000020.':
   ('Fehler: SDO-Schreibzugriffe auf dieses Objekt brechen mit 0x08000020 ab.', '故障：对此对象的 SDO 写入以 0x08000020 中止。'),
 'IDX:SUB': ('IDX:SUB', 'IDX:SUB'),
 '--can-plugin is required (available: %1)': ('--can-plugin ist erforderlich (verfügbar: %1)', '必须给出 --can-plugin（可用：%1）'),
 "--can-plugin: unknown plugin '%1' (available: %2)": ("--can-plugin: unbekanntes Plugin '%1' (verfügbar: %2)", "--can-plugin：未知插件 '%1'（可用：%2）"),
 '--can-interface is required, e.g. can0 or tcp://127.0.0.1:35468/can0':
   ('--can-interface ist erforderlich, z. B. can0 oder tcp://127.0.0.1:35468/can0', '必须给出 --can-interface，例如 can0 或 tcp://127.0.0.1:35468/can0'),
 "--drop-fraction: '%1' is not a fraction from 0 to 1": ("--drop-fraction: '%1' ist kein Anteil von 0 bis 1", "--drop-fraction：'%1' 不是 0 到 1 之间的比例"),
 "--emcy-at-sample: '%1' is too large": ("--emcy-at-sample: '%1' ist zu groß", "--emcy-at-sample：'%1' 过大"),
 'learnid-robot-sim: stopping (%1)': ('learnid-robot-sim: wird beendet (%1)', 'learnid-robot-sim：正在停止（%1）'),
 'cannot connect the CAN interface %1 with plugin %2: %3':
   ('die CAN-Schnittstelle %1 mit Plugin %2 kann nicht verbunden werden: %3', '无法用插件 %2 连接 CAN 接口 %1：%3'),
 'learnid-robot-sim: error: cannot create the CAN device %1 with plugin %2: %3':
   ('learnid-robot-sim: Fehler: das CAN-Gerät %1 mit Plugin %2 kann nicht angelegt werden: %3',
    'learnid-robot-sim：错误：无法用插件 %2 创建 CAN 设备 %1：%3'),
 'learnid-robot-sim: error: --state: %1': ('learnid-robot-sim: Fehler: --state: %1', 'learnid-robot-sim：错误：--state：%1'),
 'learnid-robot-sim: silent after %1 frames (injected fault)':
   ('learnid-robot-sim: still nach %1 Frames (eingespeister Fehler)', 'learnid-robot-sim：%1 帧后静默（注入故障）'),
 'the CAN device %1 disconnected': ('das CAN-Gerät %1 hat die Verbindung getrennt', 'CAN 设备 %1 已断开'),
 'learnid-robot-sim: CAN device error: %1': ('learnid-robot-sim: Fehler des CAN-Geräts: %1', 'learnid-robot-sim：CAN 设备错误：%1'),
 'the CAN interface %1 with plugin %2 did not connect within %3 s':
   ('die CAN-Schnittstelle %1 mit Plugin %2 hat sich nicht innerhalb von %3 s verbunden', '使用插件 %2 的 CAN 接口 %1 未在 %3 s 内连接'),
 "--setpoint-timeout: '%1' is too large (at most 100000)":
   ("--setpoint-timeout: '%1' ist zu groß (höchstens 100000)", "--setpoint-timeout：'%1' 过大（最多 100000）"),
 'SYNC periods in Operation enabled without a set-point before a drive faults with EMCY 0x8100 (default 3; raise it on a heavily loaded machine).':
   ('SYNC-Perioden in Betrieb freigegeben ohne Sollwert, bevor ein Antrieb mit EMCY 0x8100 in Fehler geht (Standard 3; auf einem stark ausgelasteten Rechner erhöhen).',
    '驱动器在运行使能状态下无设定值多少个 SYNC 周期后以 EMCY 0x8100 报故障（默认 3；在负载很重的机器上请调高）。'),
}

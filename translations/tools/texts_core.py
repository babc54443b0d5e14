"""Translations of core/ outside CAN (files, validation, safety checks, session, models, simulated
robot): source text -> (German, Chinese)."""

T = {
 # io/AtomicFile, io/OutputPath
 'cannot write %1: %2': ('%1 kann nicht geschrieben werden: %2', '无法写入 %1：%2'),
 'no file name given': ('kein Dateiname angegeben', '未给出文件名'),
 'the same file is to be written twice': ('dieselbe Datei soll zweimal geschrieben werden', '同一文件将被写入两次'),
 '%1 (already written: %2)': ('%1 (bereits geschrieben: %2)', '%1（已写入：%2）'),
 'cannot read %1: %2': ('%1 kann nicht gelesen werden: %2', '无法读取 %1：%2'),
 '%1: no path given': ('%1: kein Pfad angegeben', '%1：未给出路径'),
 '%1: %2 is relative, and the folder it is taken from, %3, does not exist or is not a folder':
   ('%1: %2 ist relativ, und der Ordner, ab dem er gilt, %3, existiert nicht oder ist kein Ordner',
    '%1：%2 是相对路径，而其基准文件夹 %3 不存在或不是文件夹'),
 # io/JsonReader
 '%1 (beyond the range of a double)': ('%1 (außerhalb des Wertebereichs von double)', '%1（超出 double 的范围）'),
 'an array': ('ein Array', '数组'),
 'an object': ('ein Objekt', '对象'),
 'nothing': ('nichts', '空'),
 'an integer from %1 to %2': ('eine ganze Zahl von %1 bis %2', '%1 到 %2 之间的整数'),
 '%1: the file is empty; expected a JSON object': ('%1: die Datei ist leer; erwartet wird ein JSON-Objekt', '%1：文件为空；应为 JSON 对象'),
 '%1: invalid JSON at line %2, column %3 (byte offset %4): %5':
   ('%1: ungültiges JSON in Zeile %2, Spalte %3 (Byte-Offset %4): %5', '%1：第 %2 行第 %3 列（字节偏移 %4）处 JSON 无效：%5'),
 '%1: the top level must be a JSON object, got %2':
   ('%1: die oberste Ebene muss ein JSON-Objekt sein, gefunden: %2', '%1：顶层必须是 JSON 对象，实际为 %2'),
 'a single value': ('ein einzelner Wert', '单个值'),
 'must be a finite number, got %1, which is beyond the range of a double':
   ('muss eine endliche Zahl sein, gefunden: %1, außerhalb des Wertebereichs von double',
    '必须是有限数，实际为 %1，超出 double 的范围'),
 'must be a number, got %1': ('muss eine Zahl sein, gefunden: %1', '必须是数字，实际为 %1'),
 'must be a finite number, got %1': ('muss eine endliche Zahl sein, gefunden: %1', '必须是有限数，实际为 %1'),
 'must be %1, got %2': ('muss %1 sein, gefunden: %2', '必须是%1，实际为 %2'),
 'must be a string, got %1': ('muss eine Zeichenkette sein, gefunden: %1', '必须是字符串，实际为 %1'),
 'must be true or false, got %1': ('muss true oder false sein, gefunden: %1', '必须是 true 或 false，实际为 %1'),
 'must be an array, got %1': ('muss ein Array sein, gefunden: %1', '必须是数组，实际为 %1'),
 'must be an object, got %1': ('muss ein Objekt sein, gefunden: %1', '必须是对象，实际为 %1'),
 'is missing; this key is required': ('fehlt; dieser Schlüssel ist erforderlich', '缺失；此键为必需项'),
 'unknown key; allowed here: %1': ('unbekannter Schlüssel; hier erlaubt: %1', '未知的键；此处允许：%1'),
 # io/ValueChecks, io/ScenarioFile
 'must be a positive number, got %1': ('muss eine positive Zahl sein, gefunden: %1', '必须是正数，实际为 %1'),
 'must be zero or a positive number, got %1': ('muss null oder eine positive Zahl sein, gefunden: %1', '必须是零或正数，实际为 %1'),
 'must be zero, a positive number or unbounded (null), got %1':
   ('muss null, eine positive Zahl oder unbegrenzt (null) sein, gefunden: %1', '必须是零、正数或无界（null），实际为 %1'),
 'must be from %1 to %2': ('muss zwischen %1 und %2 liegen', '必须在 %1 到 %2 之间'),
 'must be greater than %1 and at most %2': ('muss größer als %1 und höchstens %2 sein', '必须大于 %1 且不超过 %2'),
 'must be greater than %1 and less than %2': ('muss größer als %1 und kleiner als %2 sein', '必须大于 %1 且小于 %2'),
 '%1, got %2': ('%1, gefunden: %2', '%1，实际为 %2'),
 'must have %1 entries (%2), got %3': ('muss %1 Einträge haben (%2), gefunden: %3', '必须有 %1 个条目（%2），实际为 %3'),
 '1 or -1': ('1 oder -1', '1 或 -1'),
 'must have 2 entries (x and y), got %1': ('muss 2 Einträge haben (x und y), gefunden: %1', '必须有 2 个条目（x 和 y），实际为 %1'),
 'one per joint': ('einer pro Gelenk', '每个关节一个'),
 'must be 1 or -1, got %1': ('muss 1 oder -1 sein, gefunden: %1', '必须是 1 或 -1，实际为 %1'),
 'must be 0 (an ideal encoder) or an integer from %1 to %2, got %3':
   ('muss 0 (idealer Encoder) oder eine ganze Zahl von %1 bis %2 sein, gefunden: %3',
    '必须是 0（理想编码器）或 %1 到 %2 之间的整数，实际为 %3'),
 # io/ParameterFile, io/ParameterDcf
 'does not fit a REAL32 object entry, got %1': ('passt nicht in einen REAL32-Objekteintrag, gefunden: %1', '无法放入 REAL32 对象条目，实际为 %1'),
 'DCF fragment: joint %1 does not exist; the robot has %2 joints':
   ('DCF-Fragment: Gelenk %1 existiert nicht; der Roboter hat %2 Gelenke', 'DCF 片段：关节 %1 不存在；机器人有 %2 个关节'),
 'must be given for every parameter or for none': ('muss für jeden Parameter oder für keinen angegeben sein', '必须为每个参数都给出，或都不给出'),
 'must be an object index written as "0x" and four hex digits, got "%1"':
   ('muss ein Objektindex aus „0x“ und vier Hexadezimalziffern sein, gefunden: „%1“',
    '必须是以“0x”加四位十六进制数字写成的对象索引，实际为“%1”'),
 'must be the bytes written as pairs of hex digits, got "%1"':
   ('müssen die geschriebenen Bytes als Paare von Hexadezimalziffern sein, gefunden: „%1“',
    '必须是以成对十六进制数字表示的写入字节，实际为“%1”'),
 'must be a date and time as in 2024-05-01T12:00:00.000Z, got "%1"':
   ('muss Datum und Uhrzeit wie 2024-05-01T12:00:00.000Z sein, gefunden: „%1“',
    '必须是形如 2024-05-01T12:00:00.000Z 的日期时间，实际为“%1”'),
 'is missing; this is not a learnid parameter file': ('fehlt; dies ist keine learnid-Parameterdatei', '缺失；这不是 learnid 参数文件'),
 'this version of learnid reads "%1", got %2': ('diese Version von learnid liest „%1“, gefunden: %2', '此版本的 learnid 读取“%1”，实际为 %2'),
 'does not match the content: the file was changed after learnid wrote it, or is damaged':
   ('passt nicht zum Inhalt: die Datei wurde nach dem Schreiben durch learnid geändert oder ist beschädigt',
    '与内容不符：文件在 learnid 写入后被修改，或已损坏'),
 '%1: %2': ('%1: %2', '%1：%2'),
 'unknown model "%1"; known models: %2': ('unbekanntes Modell „%1“; bekannte Modelle: %2', '未知模型“%1”；已知模型：%2'),
 'one per joint of %1': ('einer pro Gelenk von %1', '%1 的每个关节一个'),
 'node %1 is given to two joints': ('Knoten %1 ist zwei Gelenken zugeordnet', '节点 %1 被分配给两个关节'),
 'must be a valid date and time': ('muss ein gültiges Datum mit Uhrzeit sein', '必须是有效的日期时间'),
 'must not be empty': ('darf nicht leer sein', '不得为空'),
 'unknown learning law "%1"; known laws: %2': ('unbekanntes Lerngesetz „%1“; bekannte Gesetze: %2', '未知学习律“%1”；已知学习律：%2'),
 'must be a trial index or -1 (not recorded), got %1':
   ('muss ein Versuchsindex oder -1 (nicht aufgezeichnet) sein, gefunden: %1', '必须是试验索引或 -1（未记录），实际为 %1'),
 'one per parameter of %1': ('einer pro Parameter von %1', '%1 的每个参数一个'),
 'must be "%1" (parameter %2 of %3), got "%4"': ('muss „%1“ sein (Parameter %2 von %3), gefunden: „%4“', '必须是“%1”（%3 的参数 %2），实际为“%4”'),
 'values, %1': ('Werte, %1', '数值，%1'),
 'standard deviations, %1': ('Standardabweichungen, %1', '标准差，%1'),
 'must name the CANopen data type': ('muss den CANopen-Datentyp nennen', '必须指明 CANopen 数据类型'),
 'must hold the bytes written': ('muss die geschriebenen Bytes enthalten', '必须包含写入的字节'),
 # io/TrialCsv, io/SessionReport
 '%1: line %2: %3': ('%1: Zeile %2: %3', '%1：第 %2 行：%3'),
 'trial CSV: the record (%1 joints, %2 samples) does not fit its plan (%3 joints, %4 samples)':
   ('Versuchs-CSV: die Aufzeichnung (%1 Gelenke, %2 Abtastwerte) passt nicht zu ihrem Plan (%3 Gelenke, %4 Abtastwerte)',
    '试验 CSV：记录（%1 个关节，%2 个采样点）与其计划（%3 个关节，%4 个采样点）不符'),
 'the file is empty; expected the header line': ('die Datei ist leer; erwartet wird die Kopfzeile', '文件为空；应有表头行'),
 'the header must be %1 (for one or more joints), got %2':
   ('die Kopfzeile muss %1 lauten (für ein oder mehrere Gelenke), gefunden: %2', '表头必须是 %1（适用于一个或多个关节），实际为 %2'),
 'expected %1 fields, got %2': ('%1 Felder erwartet, gefunden: %2', '应有 %1 个字段，实际为 %2'),
 '%1 is not a number: "%2"': ('%1 ist keine Zahl: „%2“', '%1 不是数字：“%2”'),
 't_s must be finite and increase from line to line, got %1':
   ('t_s muss endlich sein und von Zeile zu Zeile zunehmen, gefunden: %1', 't_s 必须有限且逐行递增，实际为 %1'),
 'estimate %1 does not exist in this session': ('Schätzung %1 existiert in dieser Sitzung nicht', '本会话中不存在估计 %1'),
 # identify/, motion/, model/
 'no completed trial to learn from': ('kein abgeschlossener Versuch, aus dem gelernt werden kann', '没有可供学习的已完成试验'),
 'trial record does not match its plan: %1 of %2 samples, %3 joints recorded for a %4-joint model':
   ('Versuchsaufzeichnung passt nicht zu ihrem Plan: %1 von %2 Abtastwerten, %3 Gelenke aufgezeichnet für ein Modell mit %4 Gelenken',
    '试验记录与其计划不符：%2 个采样点中记录了 %1 个，%4 关节模型记录了 %3 个关节'),
 'trial record has only %1 samples': ('Versuchsaufzeichnung hat nur %1 Abtastwerte', '试验记录只有 %1 个采样点'),
 'trial record has a non-finite %1 at sample %2, joint %3':
   ('Versuchsaufzeichnung hat einen nicht endlichen Wert (%1) bei Abtastwert %2, Gelenk %3',
    '试验记录在采样点 %2、关节 %3 处有非有限的%1'),
 'torque': ('Moment', '力矩'),
 'angle': ('Winkel', '角度'),
 'least squares sizes do not match: %1 x %2 regressor, %3 targets, %4 joints, %5 parameters':
   ('Größen der kleinsten Quadrate passen nicht: %1 x %2 Regressor, %3 Zielwerte, %4 Gelenke, %5 Parameter',
    '最小二乘维度不匹配：%1 x %2 回归矩阵，%3 个目标值，%4 个关节，%5 个参数'),
 'the regressor or the torque contains non-finite values':
   ('der Regressor oder das Moment enthält nicht endliche Werte', '回归矩阵或力矩包含非有限值'),
 'invalid timing: sample period and duration must be positive, rests non-negative':
   ('ungültiger Zeitablauf: Abtastzeit und Dauer müssen positiv sein, Ruhezeiten nicht negativ',
    '时序无效：采样周期和持续时间必须为正，静止时间不得为负'),
 'a planar line needs 2 joints': ('eine ebene Gerade braucht 2 Gelenke', '平面直线需要 2 个关节'),
 'torque rule needs 2 grid points': ('die Momentenregel braucht 2 Stützstellen', '力矩规则需要 2 个网格点'),
 'torque rule needs one positive limit per joint and a positive fraction':
   ('die Momentenregel braucht eine positive Grenze pro Gelenk und einen positiven Anteil',
    '力矩规则需要每个关节一个正的限值和一个正的比例'),
 "gravity alone needs more than %1 % of a joint's torque limit":
   ('die Schwerkraft allein braucht mehr als %1 % der Momentengrenze eines Gelenks', '仅重力就需要超过某关节力矩限值的 %1 %'),
 'the path needs no torque: check its length and the parameters':
   ('die Bahn braucht kein Moment: Länge und Parameter prüfen', '该路径不需要力矩：请检查其长度和参数'),
 'only planar 2-link arms have Cartesian line kinematics':
   ('nur ebene Zweigelenkarme haben eine kartesische Geradenkinematik', '只有平面二连杆机械臂具有笛卡尔直线运动学'),
 'inertia of the base axis': ('Trägheit der Basisachse', '基座轴的惯量'),
 'coupling inertia of the two links': ('Koppelträgheit der beiden Glieder', '两连杆的耦合惯量'),
 'inertia of the second link': ('Trägheit des zweiten Glieds', '第二连杆的惯量'),
 'point (%1, %2) m is out of reach or at a singularity of the arm (link lengths %3 m and %4 m)':
   ('Punkt (%1, %2) m ist außer Reichweite oder in einer Singularität des Arms (Gliedlängen %3 m und %4 m)',
    '点 (%1, %2) m 超出机械臂的工作范围或处于奇异位形（连杆长度 %3 m 和 %4 m）'),
 # robot/, session/
 'completed': ('abgeschlossen', '已完成'),
 'aborted': ('abgebrochen', '已中止'),
 'robot fault': ('Roboterfehler', '机器人故障'),
 'cancelled': ('vom Bediener gestoppt', '已取消'),
 'refused': ('abgelehnt', '已拒绝'),
 'simulated %1': ('Simulation %1', '仿真 %1'),
 'tracking error of joint %1 reached %2 deg at t = %3 s (limit %4 deg): quick stop':
   ('Folgefehler von Gelenk %1 erreichte %2° bei t = %3 s (Grenze %4°): Schnellhalt',
    '关节 %1 的跟踪误差在 t = %3 s 时达到 %2 度（限值 %4 度）：快速停止'),
 'drive of joint 1 reported a fault at t = %1 s (injected)':
   ('Antrieb von Gelenk 1 meldete bei t = %1 s einen Fehler (eingespeist)', '关节 1 的驱动器在 t = %1 s 时报告故障（注入）'),
 'stopped by the operator at t = %1 s': ('vom Bediener gestoppt bei t = %1 s', '操作员在 t = %1 s 时停止'),
 'the simulated controller refused the parameter write (injected fault); its stored parameters are unchanged':
   ('die simulierte Steuerung lehnte das Schreiben der Parameter ab (eingespeister Fehler); ihre gespeicherten Parameter sind unverändert',
    '仿真控制器拒绝写入参数（注入故障）；其已存储参数未改变'),
 'parameter set has %1 values, the model needs %2 finite values':
   ('der Parametersatz hat %1 Werte, das Modell braucht %2 endliche Werte', '参数组有 %1 个值，模型需要 %2 个有限值'),
 'the estimate is not a physical robot: its mass matrix is not positive definite at t = %1 s':
   ('die Schätzung ist kein physikalischer Roboter: ihre Massenmatrix ist bei t = %1 s nicht positiv definit',
    '该估计不是物理上可能的机器人：其质量矩阵在 t = %1 s 时不是正定的'),
 'the closed loop would be unstable: linearised along the path with the current estimate, a pole has |z| = %1 (growth rate %2 1/s) at t = %3 s. Raise the derivative filter bandwidth lambda or lower the gains':
   ('der Regelkreis wäre instabil: entlang der Bahn mit der aktuellen Schätzung linearisiert, hat ein Pol bei t = %3 s |z| = %1 (Wachstumsrate %2 1/s). Die Bandbreite lambda des Differenzierfilters erhöhen oder die Verstärkungen senken',
    '闭环将不稳定：用当前估计沿路径线性化后，在 t = %3 s 时有一个极点 |z| = %1（增长率 %2 1/s）。请提高微分滤波器带宽 lambda 或降低增益'),
 'planned torque of joint %1 is %2 N m, above its limit of %3 N m':
   ('geplantes Moment von Gelenk %1 ist %2 N m, über seiner Grenze von %3 N m', '关节 %1 的计划力矩为 %2 N m，超过其限值 %3 N m'),
 "unknown estimator law '%1' (known: %2)": ("unbekanntes Schätzgesetz '%1' (bekannt: %2)", "未知估计律 '%1'（已知：%2）"),
 'scenario does not fit the %1 model: it needs %2 parameters and %3 joint limits and gains':
   ('Szenario passt nicht zum Modell %1: es braucht %2 Parameter und %3 Gelenkgrenzen und Verstärkungen',
    '场景不适合 %1 模型：它需要 %2 个参数以及 %3 个关节的限值和增益'),
 'trial %1 refused before motion: %2': ('Versuch %1 vor der Bewegung abgelehnt: %2', '试验 %1 在运动前被拒绝：%2'),
 'repetition %1 of %2: %3': ('Wiederholung %1 von %2: %3', '第 %1 次重复（共 %2 次）：%3'),
 'the update produced non-finite parameters': ('die Aktualisierung ergab nicht endliche Parameter', '更新产生了非有限参数'),
 'trial %1 not learned from: %2': ('aus Versuch %1 nicht gelernt: %2', '未从试验 %1 学习：%2'),
 'there is no learned estimate to accept yet: run a trial first':
   ('es gibt noch keine gelernte Schätzung zum Akzeptieren: zuerst einen Versuch ausführen', '尚无可接受的学习估计：请先运行一次试验'),
 'estimate %1 does not exist: choose 1 to %2': ('Schätzung %1 existiert nicht: 1 bis %2 wählen', '估计 %1 不存在：请选择 1 到 %2'),
 'nothing accepted: accept an estimate before applying it':
   ('nichts akzeptiert: eine Schätzung akzeptieren, bevor sie übertragen wird', '未接受任何估计：请先接受估计再写入'),
 'nothing to revert: no parameter set has been applied in this session':
   ('nichts zurückzunehmen: in dieser Sitzung wurde kein Parametersatz übertragen', '无可撤销内容：本会话中尚未写入任何参数组'),
 'the robot held no parameter set before the first apply; there is nothing to restore':
   ('der Roboter hatte vor dem ersten Übertragen keinen Parametersatz; es gibt nichts wiederherzustellen',
    '首次写入前机器人没有参数组；无可恢复内容'),
}

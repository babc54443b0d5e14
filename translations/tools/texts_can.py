"""Translations of CANopen texts (core/can, core/canrobot, core/cansim): source text -> (German,
Chinese). SDO, PDO, EMCY, NMT, SYNC, TPDO, RPDO, object names and numbers stay as they are; the
CiA 402 states are named as in German CiA documents (Betrieb freigegeben, Schnellhalt aktiv ...)."""

T = {
 # can/Cia402: drive states
 'Not ready to switch on': ('Nicht einschaltbereit', '未准备好接通'),
 'Switch on disabled': ('Einschaltsperre', '接通禁止'),
 'Ready to switch on': ('Einschaltbereit', '准备接通'),
 'Switched on': ('Eingeschaltet', '已接通'),
 'Operation enabled': ('Betrieb freigegeben', '运行使能'),
 'Quick stop active': ('Schnellhalt aktiv', '快速停止激活'),
 'Fault reaction active': ('Fehlerreaktion aktiv', '故障反应激活'),
 'Fault': ('Fehler', '故障'),
 'Unknown drive state': ('Unbekannter Antriebszustand', '未知驱动器状态'),
 # can/Nmt: NMT states keep their CANopen names
 'boot-up': ('Boot-up', '启动（boot-up）'),
 'stopped': ('Stopped', '停止（stopped）'),
 'operational': ('Operational', '运行（operational）'),
 'pre-operational': ('Pre-Operational', '预运行（pre-operational）'),
 # can/SdoAbortCode (CiA 301)
 'Toggle bit not alternated.': ('Toggle-Bit nicht gewechselt.', '触发位未交替。'),
 'SDO protocol timed out.': ('Zeitüberschreitung im SDO-Protokoll.', 'SDO 协议超时。'),
 'Client/server command specifier not valid or unknown.':
   ('Client/Server-Kommandokennung ungültig oder unbekannt.', '客户端/服务器命令说明符无效或未知。'),
 'Invalid block size (block mode only).': ('Ungültige Blockgröße (nur Blockmodus).', '块大小无效（仅块模式）。'),
 'Invalid sequence number (block mode only).': ('Ungültige Sequenznummer (nur Blockmodus).', '序列号无效（仅块模式）。'),
 'CRC error (block mode only).': ('CRC-Fehler (nur Blockmodus).', 'CRC 错误（仅块模式）。'),
 'Out of memory.': ('Kein Speicher mehr.', '内存不足。'),
 'Unsupported access to an object.': ('Nicht unterstützter Zugriff auf ein Objekt.', '不支持的对象访问。'),
 'Attempt to read a write-only object.': ('Versuch, ein nur schreibbares Objekt zu lesen.', '试图读取只写对象。'),
 'Attempt to write a read-only object.': ('Versuch, ein nur lesbares Objekt zu schreiben.', '试图写入只读对象。'),
 'Object does not exist in the object dictionary.': ('Objekt existiert nicht im Objektverzeichnis.', '对象字典中不存在该对象。'),
 'Object cannot be mapped to the PDO.': ('Objekt kann nicht in das PDO gemappt werden.', '对象无法映射到 PDO。'),
 'The number and length of the objects to be mapped would exceed the PDO length.':
   ('Anzahl und Länge der zu mappenden Objekte würden die PDO-Länge überschreiten.', '待映射对象的数量和长度将超出 PDO 长度。'),
 'General parameter incompatibility.': ('Allgemeine Parameterunverträglichkeit.', '一般参数不兼容。'),
 'General internal incompatibility in the device.': ('Allgemeine interne Unverträglichkeit im Gerät.', '设备内部一般不兼容。'),
 'Access failed due to a hardware error.': ('Zugriff wegen eines Hardwarefehlers fehlgeschlagen.', '因硬件错误访问失败。'),
 'Data type does not match: the length of the service parameter does not match.':
   ('Datentyp passt nicht: die Länge des Dienstparameters passt nicht.', '数据类型不匹配：服务参数的长度不匹配。'),
 'Data type does not match: the length of the service parameter is too high.':
   ('Datentyp passt nicht: die Länge des Dienstparameters ist zu groß.', '数据类型不匹配：服务参数的长度过长。'),
 'Data type does not match: the length of the service parameter is too low.':
   ('Datentyp passt nicht: die Länge des Dienstparameters ist zu klein.', '数据类型不匹配：服务参数的长度过短。'),
 'Sub-index does not exist.': ('Subindex existiert nicht.', '子索引不存在。'),
 'Invalid value for the parameter (download only).': ('Ungültiger Wert für den Parameter (nur Download).', '参数值无效（仅下载）。'),
 'Value of the parameter written too high (download only).':
   ('Geschriebener Parameterwert zu hoch (nur Download).', '写入的参数值过高（仅下载）。'),
 'Value of the parameter written too low (download only).':
   ('Geschriebener Parameterwert zu niedrig (nur Download).', '写入的参数值过低（仅下载）。'),
 'Maximum value is less than minimum value.': ('Maximalwert ist kleiner als Minimalwert.', '最大值小于最小值。'),
 'Resource not available: SDO connection.': ('Ressource nicht verfügbar: SDO-Verbindung.', '资源不可用：SDO 连接。'),
 'General error.': ('Allgemeiner Fehler.', '一般错误。'),
 'Data cannot be transferred or stored to the application.':
   ('Daten können nicht zur Anwendung übertragen oder dort gespeichert werden.', '数据无法传输或存储到应用。'),
 'Data cannot be transferred or stored to the application because of local control.':
   ('Daten können wegen lokaler Steuerung nicht zur Anwendung übertragen oder dort gespeichert werden.',
    '因本地控制，数据无法传输或存储到应用。'),
 'Data cannot be transferred or stored to the application because of the present device state.':
   ('Daten können wegen des aktuellen Gerätezustands nicht zur Anwendung übertragen oder dort gespeichert werden.',
    '因当前设备状态，数据无法传输或存储到应用。'),
 'Object dictionary dynamic generation failed or no object dictionary is present.':
   ('Dynamisches Erzeugen des Objektverzeichnisses fehlgeschlagen oder kein Objektverzeichnis vorhanden.',
    '对象字典动态生成失败或不存在对象字典。'),
 'No data available.': ('Keine Daten verfügbar.', '无可用数据。'),
 'Unknown abort code %1.': ('Unbekannter Abbruchcode %1.', '未知中止代码 %1。'),
 # can/EmcyConsumer: error code classes and error register bits (CiA 301, CiA 402)
 'error reset or no error': ('Fehler zurückgesetzt oder kein Fehler', '错误复位或无错误'),
 'generic error': ('allgemeiner Fehler', '一般错误'),
 'current': ('Strom', '电流'),
 'current, device input side': ('Strom, Geräteeingangsseite', '电流，设备输入侧'),
 'current inside the device': ('Strom im Gerät', '设备内部电流'),
 'current, device output side': ('Strom, Geräteausgangsseite', '电流，设备输出侧'),
 'continuous over-current': ('Dauerüberstrom', '持续过流'),
 'short circuit or earth leakage': ('Kurzschluss oder Erdschluss', '短路或接地泄漏'),
 'voltage': ('Spannung', '电压'),
 'mains voltage': ('Netzspannung', '电网电压'),
 'voltage inside the device': ('Spannung im Gerät', '设备内部电压'),
 'DC link over-voltage': ('Zwischenkreisüberspannung', '直流母线过压'),
 'DC link under-voltage': ('Zwischenkreisunterspannung', '直流母线欠压'),
 'output voltage': ('Ausgangsspannung', '输出电压'),
 'temperature': ('Temperatur', '温度'),
 'ambient temperature': ('Umgebungstemperatur', '环境温度'),
 'device temperature': ('Gerätetemperatur', '设备温度'),
 'drive excess temperature': ('Übertemperatur des Antriebs', '驱动器过温'),
 'device hardware': ('Gerätehardware', '设备硬件'),
 'device software': ('Gerätesoftware', '设备软件'),
 'internal software': ('interne Software', '内部软件'),
 'user software': ('Anwendersoftware', '用户软件'),
 'data set': ('Datensatz', '数据集'),
 'additional modules': ('Zusatzmodule', '附加模块'),
 'sensor': ('Sensor', '传感器'),
 'incremental sensor 1 fault': ('Fehler Inkrementalgeber 1', '增量传感器 1 故障'),
 'monitoring': ('Überwachung', '监控'),
 'communication': ('Kommunikation', '通信'),
 'CAN overrun (objects lost)': ('CAN-Überlauf (Objekte verloren)', 'CAN 溢出（对象丢失）'),
 'CAN in error passive mode': ('CAN im Zustand Error Passive', 'CAN 处于错误被动模式'),
 'life guard or heartbeat error': ('Life-Guarding- oder Heartbeat-Fehler', '节点保护或心跳错误'),
 'recovered from bus off': ('von Bus-Off erholt', '已从总线关闭恢复'),
 'CAN-ID collision': ('CAN-ID-Kollision', 'CAN-ID 冲突'),
 'protocol error': ('Protokollfehler', '协议错误'),
 'PDO not processed due to length error': ('PDO wegen Längenfehler nicht verarbeitet', '因长度错误未处理 PDO'),
 'PDO length exceeded': ('PDO-Länge überschritten', '超出 PDO 长度'),
 'unexpected SYNC data length': ('unerwartete SYNC-Datenlänge', '意外的 SYNC 数据长度'),
 'RPDO timeout': ('RPDO-Zeitüberschreitung', 'RPDO 超时'),
 'positioning controller': ('Lageregler', '位置控制器'),
 'following error': ('Schleppfehler', '跟随误差'),
 'external error': ('externer Fehler', '外部错误'),
 'additional functions': ('Zusatzfunktionen', '附加功能'),
 'device specific': ('gerätespezifisch', '设备特定'),
 'generic': ('allgemein', '一般'),
 'device profile': ('Geräteprofil', '设备行规'),
 'reserved': ('reserviert', '保留'),
 'manufacturer': ('herstellerspezifisch', '制造商特定'),
 'unknown error code': ('unbekannter Fehlercode', '未知错误代码'),
 'no error': ('kein Fehler', '无错误'),
 'Node %1 emergency %2: %3; error register %4: %5; manufacturer data %6':
   ('Knoten %1 EMCY %2: %3; Fehlerregister %4: %5; Herstellerdaten %6',
    '节点 %1 紧急报文（EMCY）%2：%3；错误寄存器 %4：%5；制造商数据 %6'),
 # can/BusLoad, can/CanOpen, can/Pdo, can/ObjectDictionary, can/ManufacturerObjects, can/SdoWrite
 'Bus load: joints and frames must not be negative, rates must be positive and a frame carries 0 to 8 bytes.':
   ('Buslast: Gelenke und Frames dürfen nicht negativ, Raten müssen positiv sein, und ein Frame trägt 0 bis 8 Bytes.',
    '总线负载：关节数和帧数不得为负，速率必须为正，且每帧携带 0 到 8 个字节。'),
 'Bus load: the time window and the bitrate must be positive.':
   ('Buslast: Zeitfenster und Bitrate müssen positiv sein.', '总线负载：时间窗口和比特率必须为正。'),
 '%1 % of %2 kbit/s (%3 frames/s)': ('%1 % von %2 kbit/s (%3 Frames/s)', '%2 kbit/s 的 %1 %（%3 帧/秒）'),
 'Unknown CANopen data type 0x%1.': ('Unbekannter CANopen-Datentyp 0x%1.', '未知的 CANopen 数据类型 0x%1。'),
 'Unknown CANopen data type "%1".': ('Unbekannter CANopen-Datentyp „%1“.', '未知的 CANopen 数据类型“%1”。'),
 '%1 is not a numeric type.': ('%1 ist kein numerischer Typ.', '%1 不是数值类型。'),
 'The value %1 does not fit the type %2 (range %3 to %4%5).':
   ('Der Wert %1 passt nicht in den Typ %2 (Bereich %3 bis %4%5).', '值 %1 不符合类型 %2（范围 %3 到 %4%5）。'),
 ', integers only': (', nur ganze Zahlen', '，仅限整数'),
 '%1 needs %2 bytes at offset %3, but only %4 bytes are present.':
   ('%1 braucht %2 Bytes ab Offset %3, aber nur %4 Bytes sind vorhanden.', '%1 需要从偏移 %3 开始的 %2 个字节，但只有 %4 个字节。'),
 'PDO %1 does not exist; learnid uses PDO 1 to 4.': ('PDO %1 existiert nicht; learnid nutzt PDO 1 bis 4.', 'PDO %1 不存在；learnid 使用 PDO 1 到 4。'),
 'Object %1 of type %2 cannot be mapped into a PDO.': ('Objekt %1 vom Typ %2 kann nicht in ein PDO gemappt werden.', '类型为 %2 的对象 %1 无法映射到 PDO。'),
 'The mapped objects need %1 bits; a PDO holds at most %2 bits (8 bytes).':
   ('Die gemappten Objekte brauchen %1 Bit; ein PDO fasst höchstens %2 Bit (8 Bytes).', '映射的对象需要 %1 位；一个 PDO 最多容纳 %2 位（8 字节）。'),
 'The PDO maps %1 objects but %2 values were given.':
   ('Das PDO mappt %1 Objekte, aber %2 Werte wurden angegeben.', '该 PDO 映射了 %1 个对象，但给出了 %2 个值。'),
 'PDO object %1: %2': ('PDO-Objekt %1: %2', 'PDO 对象 %1：%2'),
 'The PDO carries %1 bytes; its mapping needs %2.': ('Das PDO trägt %1 Bytes; sein Mapping braucht %2.', '该 PDO 携带 %1 个字节；其映射需要 %2 个。'),
 'Object %1: %2 is not numeric; use addBytes().': ('Objekt %1: %2 ist nicht numerisch; addBytes() verwenden.', '对象 %1：%2 不是数值类型；请使用 addBytes()。'),
 'Object %1: %2 is numeric; use add().': ('Objekt %1: %2 ist numerisch; add() verwenden.', '对象 %1：%2 是数值类型；请使用 add()。'),
 'Object %1 is defined twice.': ('Objekt %1 ist zweimal definiert.', '对象 %1 被定义了两次。'),
 'Object %1 holds %2 bytes, not %3.': ('Objekt %1 enthält %2 Bytes, nicht %3.', '对象 %1 包含 %2 个字节，而不是 %3 个。'),
 'Object %1 is not in the object dictionary.': ('Objekt %1 ist nicht im Objektverzeichnis.', '对象 %1 不在对象字典中。'),
 'No node to write the parameters to.': ('Kein Knoten, in den die Parameter geschrieben werden können.', '没有可写入参数的节点。'),
 'A parameter set holds 1 to %1 parameters, not %2.':
   ('Ein Parametersatz enthält 1 bis %1 Parameter, nicht %2.', '参数组包含 1 到 %1 个参数，而不是 %2 个。'),
 '%1 is not a valid CANopen node id (1 to 127).': ('%1 ist keine gültige CANopen-Knoten-ID (1 bis 127).', '%1 不是有效的 CANopen 节点 ID（1 到 127）。'),
 'Node %1 is listed twice.': ('Knoten %1 ist zweimal aufgeführt.', '节点 %1 被列出两次。'),
 'Parameter %1 (%2) cannot be sent as REAL32.': ('Parameter %1 (%2) kann nicht als REAL32 gesendet werden.', '参数 %1（%2）无法以 REAL32 发送。'),
 'Node %1, object %2: %3': ('Knoten %1, Objekt %2: %3', '节点 %1，对象 %2：%3'),
 # can/CandumpLog
 'the line must start with a timestamp in parentheses, e.g. (1700000000.123456)':
   ('die Zeile muss mit einem Zeitstempel in Klammern beginnen, z. B. (1700000000.123456)',
    '该行必须以括号中的时间戳开头，例如 (1700000000.123456)'),
 '"%1" is not a timestamp of the form (seconds.microseconds)':
   ('„%1“ ist kein Zeitstempel der Form (Sekunden.Mikrosekunden)', '“%1”不是 (秒.微秒) 形式的时间戳'),
 '"%1" has no \'#\' between identifier and data': ('„%1“ hat kein \'#\' zwischen Identifier und Daten', '“%1”在标识符和数据之间没有 \'#\''),
 'CAN FD frames are not supported': ('CAN-FD-Frames werden nicht unterstützt', '不支持 CAN FD 帧'),
 '"%1" is not an identifier of 3 (standard) or 8 (extended) hex digits':
   ('„%1“ ist kein Identifier aus 3 (Standard) oder 8 (erweitert) Hexadezimalziffern', '“%1”不是由 3 位（标准）或 8 位（扩展）十六进制数字组成的标识符'),
 'the standard identifier %1 exceeds 7FF': ('der Standard-Identifier %1 überschreitet 7FF', '标准标识符 %1 超过 7FF'),
 'the extended identifier %1 exceeds 1FFFFFFF': ('der erweiterte Identifier %1 überschreitet 1FFFFFFF', '扩展标识符 %1 超过 1FFFFFFF'),
 '"%1" is not a remote request (R, optionally with a length 0 to 8)':
   ('„%1“ ist keine Remote-Anfrage (R, wahlweise mit einer Länge 0 bis 8)', '“%1”不是远程请求（R，可带 0 到 8 的长度）'),
 '"%1" is not data of whole bytes in hex digits': ('„%1“ sind keine Daten aus ganzen Bytes in Hexadezimalziffern', '“%1”不是以十六进制数字表示的整字节数据'),
 '%1 data bytes; a classic CAN frame carries at most 8':
   ('%1 Datenbytes; ein klassischer CAN-Frame trägt höchstens 8', '%1 个数据字节；经典 CAN 帧最多携带 8 个'),
 'expected "(timestamp) interface id#data", found %1 fields':
   ('erwartet „(Zeitstempel) Schnittstelle id#Daten“, gefunden: %1 Felder', '应为“(时间戳) 接口 id#数据”，实际有 %1 个字段'),
 'unexpected text after the frame: "%1"': ('unerwarteter Text nach dem Frame: „%1“', '帧之后有意外文本：“%1”'),
 'Cannot open the candump log %1: %2': ('Das candump-Log %1 kann nicht geöffnet werden: %2', '无法打开 candump 日志 %1：%2'),
 'Writing the candump log failed: %1': ('Schreiben des candump-Logs fehlgeschlagen: %1', '写入 candump 日志失败：%1'),
 'Cannot write the candump log %1: %2': ('Das candump-Log %1 kann nicht geschrieben werden: %2', '无法写入 candump 日志 %1：%2'),
 # can/CanLink, can/MemoryCanDevice, can/SdoClient
 'The CAN device no longer exists.': ('Das CAN-Gerät existiert nicht mehr.', 'CAN 设备已不存在。'),
 'The CAN device %1 is not connected.': ('Das CAN-Gerät %1 ist nicht verbunden.', 'CAN 设备 %1 未连接。'),
 'The CAN device refused the frame: %1': ('Das CAN-Gerät hat den Frame abgelehnt: %1', 'CAN 设备拒绝了该帧：%1'),
 'The memory CAN device %1 is not attached to a bus.': ('Das Speicher-CAN-Gerät %1 hängt an keinem Bus.', '内存 CAN 设备 %1 未连接到总线。'),
 'The memory CAN device %1 refused to connect.': ('Das Speicher-CAN-Gerät %1 hat die Verbindung abgelehnt.', '内存 CAN 设备 %1 拒绝连接。'),
 'Cannot write a frame: the device %1 is not connected.':
   ('Frame kann nicht geschrieben werden: das Gerät %1 ist nicht verbunden.', '无法写入帧：设备 %1 未连接。'),
 'Cannot write an invalid or CAN FD frame: %1.': ('Ein ungültiger oder CAN-FD-Frame kann nicht geschrieben werden: %1.', '无法写入无效帧或 CAN FD 帧：%1。'),
 'Only data and remote request frames can be written.': ('Nur Daten- und Remote-Frames können geschrieben werden.', '只能写入数据帧和远程请求帧。'),
 'The memory CAN device %1 failed to write the frame.': ('Das Speicher-CAN-Gerät %1 konnte den Frame nicht schreiben.', '内存 CAN 设备 %1 写入帧失败。'),
 'CAN error frame, error classes 0x%1.': ('CAN-Fehlerframe, Fehlerklassen 0x%1.', 'CAN 错误帧，错误类别 0x%1。'),
 'There are no data to write.': ('Es gibt keine Daten zum Schreiben.', '没有要写入的数据。'),
 'The answer names another object.': ('Die Antwort nennt ein anderes Objekt.', '应答指向了另一个对象。'),
 'The node announced %1 bytes but sent %2%3.': ('Der Knoten kündigte %1 Bytes an, sandte aber %2%3.', '节点声明 %1 个字节，但发送了 %2%3。'),
 ' or more': (' oder mehr', ' 或更多'),
 'SDO read of %1 from node %2': ('SDO-Lesen von %1 aus Knoten %2', '从节点 %2 SDO 读取 %1'),
 'SDO write of %1 to node %2': ('SDO-Schreiben von %1 in Knoten %2', '向节点 %2 SDO 写入 %1'),
 ' (abort code %1)': (' (Abbruchcode %1)', '（中止代码 %1）'),
 'The %1 was refused by the node%2: %3': ('%1 wurde vom Knoten abgelehnt%2: %3', '%1 被节点拒绝%2：%3'),
 'The %1 was aborted%2: %3': ('%1 wurde abgebrochen%2: %3', '%1 已中止%2：%3'),
 'The %1 failed: %2': ('%1 ist fehlgeschlagen: %2', '%1 失败：%2'),
 'node %1 did not answer within %2 ms.': ('Knoten %1 hat nicht innerhalb von %2 ms geantwortet.', '节点 %1 未在 %2 ms 内应答。'),
 # canrobot/
 'node %1, object %2: read back %3 after writing %4 (%5 %6): nothing was stored':
   ('Knoten %1, Objekt %2: nach dem Schreiben von %4 (%5 %6) %3 zurückgelesen: nichts wurde gespeichert',
    '节点 %1，对象 %2：写入 %4（%5 %6）后回读为 %3：未存储任何内容'),
 'CAN %1/%2, nodes %3': ('CAN %1/%2, Knoten %3', 'CAN %1/%2，节点 %3'),
 'cannot create the CAN device %1/%2: %3': ('das CAN-Gerät %1/%2 kann nicht angelegt werden: %3', '无法创建 CAN 设备 %1/%2：%3'),
 'unknown plugin or interface': ('unbekanntes Plugin oder unbekannte Schnittstelle', '未知插件或接口'),
 'no CAN node given: one node per joint is needed': ('kein CAN-Knoten angegeben: ein Knoten pro Gelenk ist nötig', '未给出 CAN 节点：每个关节需要一个节点'),
 '%1 is not a valid CANopen node id (1 to 127)': ('%1 ist keine gültige CANopen-Knoten-ID (1 bis 127)', '%1 不是有效的 CANopen 节点 ID（1 到 127）'),
 'node %1 is listed twice': ('Knoten %1 ist zweimal aufgeführt', '节点 %1 被列出两次'),
 'CAN timing options must be positive (heartbeat period at most 65535 ms)':
   ('CAN-Zeitoptionen müssen positiv sein (Heartbeat-Periode höchstens 65535 ms)', 'CAN 定时选项必须为正（心跳周期最多 65535 ms）'),
 'the configuration of %1 nodes at %2 Hz needs %3 of the bus, more than the %4 % the tool allows: use fewer nodes per bus or a longer SYNC period':
   ('die Konfiguration mit %1 Knoten bei %2 Hz braucht %3 des Busses, mehr als die %4 %, die das Werkzeug zulässt: weniger Knoten pro Bus oder eine längere SYNC-Periode verwenden',
    '%1 个节点、%2 Hz 的配置需要总线的 %3，超过本工具允许的 %4 %：请减少每条总线的节点数或延长 SYNC 周期'),
 "'%1' is not a CANopen node id (1 to 127)": ("'%1' ist keine CANopen-Knoten-ID (1 bis 127)", "'%1' 不是 CANopen 节点 ID（1 到 127）"),
 'node %1, object %2: the answer holds %3 bytes, UNSIGNED32 needs 4':
   ('Knoten %1, Objekt %2: die Antwort enthält %3 Bytes, UNSIGNED32 braucht 4', '节点 %1，对象 %2：应答包含 %3 个字节，UNSIGNED32 需要 4 个'),
 "node %1, object %2 is 0: the drive's units are unusable":
   ('Knoten %1, Objekt %2 ist 0: die Einheiten des Antriebs sind unbrauchbar', '节点 %1，对象 %2 为 0：驱动器的单位不可用'),
 'the plan is for %1 joints but %2 CAN nodes are configured':
   ('der Plan ist für %1 Gelenke, aber %2 CAN-Knoten sind konfiguriert', '计划针对 %1 个关节，但配置了 %2 个 CAN 节点'),
 'the sample period %1 ms cannot be sent to 0x60C2 (whole ms, 1 to 255)':
   ('die Abtastzeit %1 ms kann nicht an 0x60C2 gesendet werden (ganze ms, 1 bis 255)', '采样周期 %1 ms 无法发送到 0x60C2（整数毫秒，1 到 255）'),
 "node %1, object 0x1006:00: the robot's SYNC period is %2 us, the plan needs %3 us":
   ('Knoten %1, Objekt 0x1006:00: die SYNC-Periode des Roboters ist %2 us, der Plan braucht %3 us',
    '节点 %1，对象 0x1006:00：机器人的 SYNC 周期为 %2 us，计划需要 %3 us'),
 '%1: the TPDO answering SYNC %2 (counter %3) did not arrive before the next SYNC: sample missing':
   ('%1: das TPDO als Antwort auf SYNC %2 (Zähler %3) kam nicht vor dem nächsten SYNC: Abtastwert fehlt',
    '%1：响应 SYNC %2（计数器 %3）的 TPDO 未在下一个 SYNC 之前到达：采样点缺失'),
 'SYNC counter jumped from %1 to %2 after SYNC %3: %4 SYNC(s) lost':
   ('SYNC-Zähler sprang nach SYNC %3 von %1 auf %2: %4 SYNC verloren', 'SYNC %3 之后 SYNC 计数器从 %1 跳到 %2：丢失 %4 个 SYNC'),
 'joint %1: TPDO of %2 bytes, the mapping needs %3 (SYNC %4)':
   ('Gelenk %1: TPDO mit %2 Bytes, das Mapping braucht %3 (SYNC %4)', '关节 %1：TPDO 为 %2 个字节，映射需要 %3 个（SYNC %4）'),
 'the CAN device %1 did not connect within %2 ms (is the bus or the robot side running?)':
   ('das CAN-Gerät %1 hat sich nicht innerhalb von %2 ms verbunden (läuft der Bus oder die Roboterseite?)',
    'CAN 设备 %1 未在 %2 ms 内连接（总线或机器人端是否在运行？）'),
 'no CAN device for %1': ('kein CAN-Gerät für %1', '没有用于 %1 的 CAN 设备'),
 'cannot connect the CAN device %1: %2': ('das CAN-Gerät %1 kann nicht verbunden werden: %2', '无法连接 CAN 设备 %1：%2'),
 'no error reported (the other side may have exited)':
   ('kein Fehler gemeldet (die Gegenseite wurde vielleicht beendet)', '未报告错误（对端可能已退出）'),
 'the CAN device %1 went unconnected: %2': ('das CAN-Gerät %1 ist nicht mehr verbunden: %2', 'CAN 设备 %1 已断开连接：%2'),
 'the CAN device %1 reported a connection error: %2': ('das CAN-Gerät %1 meldete einen Verbindungsfehler: %2', 'CAN 设备 %1 报告连接错误：%2'),
 'the model has %1 joints but %2 CAN nodes are configured, or the plan is empty':
   ('das Modell hat %1 Gelenke, aber %2 CAN-Knoten sind konfiguriert, oder der Plan ist leer',
    '模型有 %1 个关节，但配置了 %2 个 CAN 节点，或计划为空'),
 'stopped by the operator before the drives moved': ('vom Bediener gestoppt, bevor sich die Antriebe bewegten', '在驱动器运动前被操作员停止'),
 'configuring the drives failed, nothing moved: %1': ('Konfigurieren der Antriebe fehlgeschlagen, nichts hat sich bewegt: %1', '配置驱动器失败，未发生任何运动：%1'),
 "the trial's candump log could not be written: %1": ('das candump-Log des Versuchs konnte nicht geschrieben werden: %1', '无法写入该试验的 candump 日志：%1'),
 '%1; the stored parameters are unchanged': ('%1; die gespeicherten Parameter sind unverändert', '%1；已存储参数未改变'),
 '%1; nothing was stored (0x1010 not written)': ('%1; nichts wurde gespeichert (0x1010 nicht geschrieben)', '%1；未存储任何内容（未写入 0x1010）'),
 '%1; storing stopped at node %2 of the list': ('%1; das Speichern stoppte bei Knoten %2 der Liste', '%1；存储在列表中的节点 %2 处停止'),
 'Cannot write a frame: the replay is not connected.':
   ('Frame kann nicht geschrieben werden: die Wiedergabe ist nicht verbunden.', '无法写入帧：回放未连接。'),
 'The master wrote %1 after the end of the log.': ('Der Master schrieb %1 nach dem Ende des Logs.', '主站在日志结束后写入了 %1。'),
 'The master wrote %1 where the log holds %2 (log frame %3): the replayed trial differs from the recorded one.':
   ('Der Master schrieb %1, wo das Log %2 enthält (Log-Frame %3): der wiedergegebene Versuch weicht vom aufgezeichneten ab.',
    '主站写入了 %1，而日志此处为 %2（日志帧 %3）：回放的试验与记录的不同。'),
 '%1 %2': ('%1 %2', '%1 %2'),
 '%1 did not reach Operation enabled within %2 ms: it reports %3 (statusword 0x%4)':
   ('%1 erreichte Betrieb freigegeben nicht innerhalb von %2 ms: meldet %3 (Statuswort 0x%4)',
    '%1 未在 %2 ms 内达到运行使能：报告为 %3（状态字 0x%4）'),
 'no TPDO': ('kein TPDO', '无 TPDO'),
 'stopped by the operator %1': ('vom Bediener gestoppt %1', '被操作员停止 %1'),
 '%1: %2 %3': ('%1: %2 %3', '%1：%2 %3'),
 '%1 left Operation enabled: it reports %2 (0x6041 = 0x%3) %4':
   ('%1 hat Betrieb freigegeben verlassen: meldet %2 (0x6041 = 0x%3) %4', '%1 离开了运行使能：报告为 %2（0x6041 = 0x%3）%4'),
 'tracking error of %1 reached %2 deg (limit %3 deg) %4: quick stop':
   ('Folgefehler von %1 erreichte %2° (Grenze %3°) %4: Schnellhalt',
    '%1 的跟踪误差达到 %2 度（限值 %3 度）%4：快速停止'),
 'only %1 of %2 samples were recorded': ('nur %1 von %2 Abtastwerten wurden aufgezeichnet', '%2 个采样点中只记录了 %1 个'),
 'at SYNC %1 (counter %2), plan sample %3, t = %4 s': ('bei SYNC %1 (Zähler %2), Planabtastwert %3, t = %4 s', '于 SYNC %1（计数器 %2），计划采样点 %3，t = %4 s'),
 'at SYNC %1 (counter %2), %3 s after NMT start': ('bei SYNC %1 (Zähler %2), %3 s nach NMT-Start', '于 SYNC %1（计数器 %2），NMT 启动后 %3 s'),
 'an unknown node': ('ein unbekannter Knoten', '未知节点'),
 'node %1 (joint %2)': ('Knoten %1 (Gelenk %2)', '节点 %1（关节 %2）'),
 'no SYNC for %1 ms: the robot side stopped sending': ('kein SYNC seit %1 ms: die Roboterseite sendet nicht mehr', '%1 ms 内无 SYNC：机器人端已停止发送'),
 'heartbeat of %1 lost: none for %2 ms (timeout %3 ms)':
   ('Heartbeat von %1 verloren: keiner seit %2 ms (Zeitgrenze %3 ms)', '%1 的心跳丢失：%2 ms 内没有心跳（超时 %3 ms）'),
 '%1 restarted on its own (boot-up message 0x%2)': ('%1 hat selbst neu gestartet (Boot-up-Nachricht 0x%2)', '%1 自行重启（boot-up 报文 0x%2）'),
 # cansim/
 'The simulated arm has no robot model.': ('Der simulierte Arm hat kein Robotermodell.', '仿真机械臂没有机器人模型。'),
 '--nodes: the %1 arm has %2 joints, so %2 node ids are needed, not %3.':
   ('--nodes: der Arm %1 hat %2 Gelenke, also werden %2 Knoten-IDs gebraucht, nicht %3.', '--nodes：%1 机械臂有 %2 个关节，因此需要 %2 个节点 ID，而不是 %3 个。'),
 '--nodes: %1 is not a CANopen node id (1 to 127).': ('--nodes: %1 ist keine CANopen-Knoten-ID (1 bis 127).', '--nodes：%1 不是 CANopen 节点 ID（1 到 127）。'),
 '--nodes: node %1 is listed twice.': ('--nodes: Knoten %1 ist zweimal aufgeführt.', '--nodes：节点 %1 被列出两次。'),
 "The simulated arm's parameters, torque limits, initial pose or gains do not fit the %1 model.":
   ('Parameter, Momentengrenzen, Anfangsstellung oder Verstärkungen des simulierten Arms passen nicht zum Modell %1.',
    '仿真机械臂的参数、力矩限值、初始位姿或增益不适合 %1 模型。'),
 'The SYNC period must be 1 to 100 ms, not %1 s.': ('Die SYNC-Periode muss 1 bis 100 ms betragen, nicht %1 s.', 'SYNC 周期必须为 1 到 100 ms，而不是 %1 s。'),
}

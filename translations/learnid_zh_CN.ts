<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>AtomicFile</name>
    <message>
        <location filename="../core/io/AtomicFile.cpp" line="+24"/>
        <source>cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>no file name given</source>
        <translation>未给出文件名</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>the same file is to be written twice</source>
        <translation>同一文件将被写入两次</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 (already written: %2)</source>
        <translation>%1（已写入：%2）</translation>
    </message>
    <message>
        <location line="+13"/>
        <location line="+5"/>
        <source>cannot read %1: %2</source>
        <translation>无法读取 %1：%2</translation>
    </message>
</context>
<context>
    <name>BaseParameters</name>
    <message>
        <location filename="../core/model/BaseParameters.cpp" line="+22"/>
        <source>base parameters need finite regressor rows</source>
        <translation>基参数需要有限的回归矩阵行</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the torques depend on no parameter: every regressor column is 0</source>
        <translation>力矩不依赖于任何参数：回归矩阵的每一列均为 0</translation>
    </message>
</context>
<context>
    <name>BoundingVolume</name>
    <message>
        <location filename="../core/model/BoundingVolume.cpp" line="+55"/>
        <source>A bounding box needs its upper corner above its lower one.</source>
        <translation>包围盒的上角必须高于下角。</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>A link without positive mass has no inertia ellipsoid.</source>
        <translation>质量不为正的连杆没有惯性椭球。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The inertia ellipsoid&apos;s margin must be above 1.</source>
        <translation>惯性椭球的裕量必须大于 1。</translation>
    </message>
</context>
<context>
    <name>BusLoad</name>
    <message>
        <location filename="../core/can/BusLoad.cpp" line="+41"/>
        <source>Bus load: joints and frames must not be negative, rates must be positive and a frame carries 0 to 8 bytes.</source>
        <translation>总线负载：关节数和帧数不得为负，速率必须为正，且每帧携带 0 到 8 个字节。</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Bus load: the time window and the bitrate must be positive.</source>
        <translation>总线负载：时间窗口和比特率必须为正。</translation>
    </message>
    <message>
        <location line="-38"/>
        <source>%1 % of %2 kbit/s (%3 frames/s)</source>
        <translation>%2 kbit/s 的 %1 %（%3 帧/秒）</translation>
    </message>
</context>
<context>
    <name>CanArmSimulator</name>
    <message>
        <location filename="../core/cansim/CanArmSimulator.cpp" line="+23"/>
        <source>The simulated arm has no robot model.</source>
        <translation>仿真机械臂没有机器人模型。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>--nodes: the %1 arm has %2 joints, so %2 node ids are needed, not %3.</source>
        <translation>--nodes：%1 机械臂有 %2 个关节，因此需要 %2 个节点 ID，而不是 %3 个。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>--nodes: %1 is not a CANopen node id (1 to 127).</source>
        <translation>--nodes：%1 不是 CANopen 节点 ID（1 到 127）。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>--nodes: node %1 is listed twice.</source>
        <translation>--nodes：节点 %1 被列出两次。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The simulated arm&apos;s parameters, torque limits, initial pose or gains do not fit the %1 model.</source>
        <translation>仿真机械臂的参数、力矩限值、初始位姿或增益不适合 %1 模型。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The SYNC period must be 1 to 100 ms, not %1 s.</source>
        <translation>SYNC 周期必须为 1 到 100 ms，而不是 %1 s。</translation>
    </message>
</context>
<context>
    <name>CanBus</name>
    <message>
        <location filename="../core/can/CanBusErrors.cpp" line="+30"/>
        <location line="+51"/>
        <source>bus off</source>
        <translation>总线关闭 (bus off)</translation>
    </message>
    <message>
        <location line="-47"/>
        <source>controller error passive (%1)</source>
        <translation>控制器错误被动 (%1)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>controller buffer overflow: frames were lost</source>
        <translation>控制器缓冲区溢出：帧已丢失</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>controller error warning level</source>
        <translation>控制器达到错误警告级别</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>controller back to error active</source>
        <translation>控制器恢复为错误主动</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>controller problem (unspecified)</source>
        <translation>控制器问题（未指明）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>transmit timeout</source>
        <translation>发送超时</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>protocol violation (type 0x%1, location 0x%2)</source>
        <translation>协议违规（类型 0x%1，位置 0x%2）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>transceiver error (0x%1)</source>
        <translation>收发器错误 (0x%1)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>no acknowledgement (no other node on the bus?)</source>
        <translation>无应答（总线上没有其他节点？）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>bus error</source>
        <translation>总线错误</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>lost arbitration</source>
        <translation>仲裁丢失</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>controller restarted</source>
        <translation>控制器已重启</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>error class 0x%1</source>
        <translation>错误类别 0x%1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>error active</source>
        <translation>错误主动</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>error warning</source>
        <translation>错误警告</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>error passive</source>
        <translation>错误被动</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>stopped</source>
        <translation>已停止</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <location filename="../core/can/SocketCanInterface.cpp" line="+142"/>
        <source>the CAN interface %1 does not exist (ip link show: is the adapter plugged in, its driver loaded?)</source>
        <translation>CAN 接口 %1 不存在（ip link show：适配器是否已插入、驱动是否已加载？）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 is not a CAN interface</source>
        <translation>%1 不是 CAN 接口</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the CAN interface %1 is down (as root: ip link set %1 type can bitrate 1000000 &amp;&amp; ip link set %1 up)</source>
        <translation>CAN 接口 %1 未启用（以 root 运行：ip link set %1 type can bitrate 1000000 &amp;&amp; ip link set %1 up）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the CAN controller of %1 is %2 (as root: ip link set %1 down &amp;&amp; ip link set %1 up; check wiring and termination)</source>
        <translation>%1 的 CAN 控制器处于 %2（以 root 运行：ip link set %1 down &amp;&amp; ip link set %1 up；请检查接线和终端电阻）</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>CAN FD (mtu %1)</source>
        <translation>CAN FD (mtu %1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAN (mtu %1)</source>
        <translation>CAN (mtu %1)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>bitrate %1 kbit/s</source>
        <translation>比特率 %1 kbit/s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bitrate not readable</source>
        <translation>比特率不可读</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: %2, %3, %4</source>
        <translation>%1：%2，%3，%4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>up</source>
        <translation>已启用</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>down</source>
        <translation>未启用</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>, driver %1</source>
        <translation>，驱动 %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>, controller %1</source>
        <translation>，控制器 %1</translation>
    </message>
</context>
<context>
    <name>CanOpen</name>
    <message>
        <location filename="../core/can/CanOpen.cpp" line="+51"/>
        <source>Unknown CANopen data type 0x%1.</source>
        <translation>未知的 CANopen 数据类型 0x%1。</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Unknown CANopen data type &quot;%1&quot;.</source>
        <translation>未知的 CANopen 数据类型“%1”。</translation>
    </message>
    <message>
        <location line="+17"/>
        <location line="+40"/>
        <source>%1 is not a numeric type.</source>
        <translation>%1 不是数值类型。</translation>
    </message>
    <message>
        <location line="-38"/>
        <source>The value %1 does not fit the type %2 (range %3 to %4%5).</source>
        <translation>值 %1 不符合类型 %2（范围 %3 到 %4%5）。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>, integers only</source>
        <translation>，仅限整数</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>%1 needs %2 bytes at offset %3, but only %4 bytes are present.</source>
        <translation>%1 需要从偏移 %3 开始的 %2 个字节，但只有 %4 个字节。</translation>
    </message>
</context>
<context>
    <name>CanRobot</name>
    <message>
        <location filename="../core/canrobot/ApplySteps.cpp" line="+27"/>
        <source>node %1, object %2: read back %3 after writing %4 (%5 %6): nothing was stored</source>
        <translation>节点 %1，对象 %2：写入 %4（%5 %6）后回读为 %3：未存储任何内容</translation>
    </message>
    <message>
        <location filename="../core/canrobot/CanRobot.cpp" line="+58"/>
        <source>CAN %1/%2, nodes %3</source>
        <translation>CAN %1/%2，节点 %3</translation>
    </message>
    <message>
        <location filename="../core/canrobot/CanRobotOptions.cpp" line="+43"/>
        <source>cannot create the CAN device %1/%2: %3</source>
        <translation>无法创建 CAN 设备 %1/%2：%3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>unknown plugin or interface</source>
        <translation>未知插件或接口</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>the configuration of %1 nodes at %2 Hz (SYNC every %3 ms) needs %4 of the bus, more than the %5 % the tool allows</source>
        <translation>%1 个节点、%2 Hz（每 %3 ms 一个 SYNC）的配置占用总线 %4，超过本工具允许的 %5 %</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1; no SYNC period up to 255 ms fits: use a faster bus</source>
        <translation>%1；255 ms 以内没有合适的 SYNC 周期：请使用更快的总线</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1; the shortest SYNC period that fits is %2 ms (%3): set the scenario&apos;s controller.samplePeriod to %4 s and the robot side&apos;s SYNC period to match</source>
        <translation>%1；可行的最短 SYNC 周期为 %2 ms（%3）：请将场景的 controller.samplePeriod 设为 %4 s，并相应设置机器人端的 SYNC 周期</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>no CAN node given: one node per joint is needed</source>
        <translation>未给出 CAN 节点：每个关节需要一个节点</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 is not a valid CANopen node id (1 to 127)</source>
        <translation>%1 不是有效的 CANopen 节点 ID（1 到 127）</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+73"/>
        <source>node %1 is listed twice</source>
        <translation>节点 %1 被列出两次</translation>
    </message>
    <message>
        <location line="-66"/>
        <source>CAN timing options must be positive (heartbeat period at most 65535 ms)</source>
        <translation>CAN 定时选项必须为正（心跳周期最多 65535 ms）</translation>
    </message>
    <message>
        <location line="+61"/>
        <source>&apos;%1&apos; is not a CANopen node id (1 to 127)</source>
        <translation>&apos;%1&apos; 不是 CANopen 节点 ID（1 到 127）</translation>
    </message>
    <message>
        <location filename="../core/canrobot/NodeConfiguration.cpp" line="+30"/>
        <source>node %1, object %2: the answer holds %3 bytes, UNSIGNED32 needs 4</source>
        <translation>节点 %1，对象 %2：应答包含 %3 个字节，UNSIGNED32 需要 4 个</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>node %1, object %2 is 0: the drive&apos;s units are unusable</source>
        <translation>节点 %1，对象 %2 为 0：驱动器的单位不可用</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>the plan is for %1 joints but %2 CAN nodes are configured</source>
        <translation>计划针对 %1 个关节，但配置了 %2 个 CAN 节点</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the sample period %1 ms cannot be sent to 0x60C2 (whole ms, 1 to 255)</source>
        <translation>采样周期 %1 ms 无法发送到 0x60C2（整数毫秒，1 到 255）</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>node %1, object 0x1006:00: the robot&apos;s SYNC period is %2 us, the plan needs %3 us</source>
        <translation>节点 %1，对象 0x1006:00：机器人的 SYNC 周期为 %2 us，计划需要 %3 us</translation>
    </message>
    <message>
        <location filename="../core/canrobot/TrialCollector.cpp" line="+41"/>
        <source>%1: the TPDO answering SYNC %2 (counter %3) did not arrive before the next SYNC: sample missing</source>
        <translation>%1：响应 SYNC %2（计数器 %3）的 TPDO 未在下一个 SYNC 之前到达：采样点缺失</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>joint %1</source>
        <translation>关节 %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>SYNC counter jumped from %1 to %2 after SYNC %3: %4 SYNC(s) lost</source>
        <translation>SYNC %3 之后 SYNC 计数器从 %1 跳到 %2：丢失 %4 个 SYNC</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>joint %1: TPDO of %2 bytes, the mapping needs %3 (SYNC %4)</source>
        <translation>关节 %1：TPDO 为 %2 个字节，映射需要 %3 个（SYNC %4）</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>at SYNC %1 (counter %2), plan sample %3, t = %4 s</source>
        <translation>于 SYNC %1（计数器 %2），计划采样点 %3，t = %4 s</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>at SYNC %1 (counter %2), %3 s after NMT start</source>
        <translation>于 SYNC %1（计数器 %2），NMT 启动后 %3 s</translation>
    </message>
    <message>
        <location filename="../core/canrobot/JointIdentityCheck.cpp" line="+23"/>
        <source>node %1, object %2: the answer holds %3 bytes, 1 to 4 expected</source>
        <translation>节点 %1，对象 %2：应答含 %3 字节，应为 1 至 4 字节</translation>
    </message>
    <message>
        <location line="+63"/>
        <source>; the drives say --nodes %1</source>
        <translation>；驱动器给出的是 --nodes %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>node %1 is listed for joint %2 but is the drive of joint %3 of this robot (0x2400:02 = %3): the node list does not match the wiring%4</source>
        <translation>节点 %1 被列为关节 %2，但它是本机器人关节 %3 的驱动器（0x2400:02 = %3）：节点列表与接线不符%4</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>node %1 (joint %2) is not the drive the parameter file records for joint %2: it reports %3 (0x1018), the file holds %4</source>
        <translation>节点 %1（关节 %2）不是参数文件为关节 %2 记录的驱动器：它报告 %3 (0x1018)，文件中为 %4</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>node %1 (joint %2) has never been commissioned (0x2400 is 0), so learnid cannot check which joint it moves: make sure it is the drive of joint %2 (its identity: %3), then run with --commission (in the window: First commissioning); apply stores the joint identity</source>
        <translation>节点 %1（关节 %2）从未调试过（0x2400 为 0），learnid 无法检查它驱动哪个关节：请确认它是关节 %2 的驱动器（其标识：%3），然后使用 --commission 运行（在窗口中：首次调试）；应用时会存储关节标识</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>node %1 (joint %2) was commissioned for another robot (0x2400:01 = %3, this robot is %4): make sure it is the drive of joint %2 (%5), then run with --commission (in the window: First commissioning)</source>
        <translation>节点 %1（关节 %2）曾为另一台机器人调试（0x2400:01 = %3，本机器人为 %4）：请确认它是关节 %2 的驱动器（%5），然后使用 --commission 运行（在窗口中：首次调试）</translation>
    </message>
</context>
<context>
    <name>CandumpLog</name>
    <message>
        <location filename="../core/can/CandumpLog.cpp" line="+52"/>
        <source>the line must start with a timestamp in parentheses, e.g. (1700000000.123456)</source>
        <translation>该行必须以括号中的时间戳开头，例如 (1700000000.123456)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&quot;%1&quot; is not a timestamp of the form (seconds.microseconds)</source>
        <translation>“%1”不是 (秒.微秒) 形式的时间戳</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>&quot;%1&quot; has no &apos;#&apos; between identifier and data</source>
        <translation>“%1”在标识符和数据之间没有 &apos;#&apos;</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>CAN FD frames are not supported</source>
        <translation>不支持 CAN FD 帧</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&quot;%1&quot; is not an identifier of 3 (standard) or 8 (extended) hex digits</source>
        <translation>“%1”不是由 3 位（标准）或 8 位（扩展）十六进制数字组成的标识符</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the standard identifier %1 exceeds 7FF</source>
        <translation>标准标识符 %1 超过 7FF</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the extended identifier %1 exceeds 1FFFFFFF</source>
        <translation>扩展标识符 %1 超过 1FFFFFFF</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>&quot;%1&quot; is not a remote request (R, optionally with a length 0 to 8)</source>
        <translation>“%1”不是远程请求（R，可带 0 到 8 的长度）</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&quot;%1&quot; is not data of whole bytes in hex digits</source>
        <translation>“%1”不是以十六进制数字表示的整字节数据</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 data bytes; a classic CAN frame carries at most 8</source>
        <translation>%1 个数据字节；经典 CAN 帧最多携带 8 个</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>expected &quot;(timestamp) interface id#data&quot;, found %1 fields</source>
        <translation>应为“(时间戳) 接口 id#数据”，实际有 %1 个字段</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>unexpected text after the frame: &quot;%1&quot;</source>
        <translation>帧之后有意外文本：“%1”</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Cannot open the candump log %1: %2</source>
        <translation>无法打开 candump 日志 %1：%2</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Writing the candump log failed: %1</source>
        <translation>写入 candump 日志失败：%1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Cannot write the candump log %1: %2</source>
        <translation>无法写入 candump 日志 %1：%2</translation>
    </message>
</context>
<context>
    <name>CartesianLine</name>
    <message>
        <location filename="../core/motion/CartesianLine.cpp" line="+53"/>
        <source>a planar line needs 2 joints</source>
        <translation>平面直线需要 2 个关节</translation>
    </message>
    <message>
        <location filename="../core/motion/MotionTiming.cpp" line="+16"/>
        <source>invalid timing: sample period and duration must be positive, rests non-negative, the sample offset within the period</source>
        <translation>时序无效：采样周期和持续时间必须为正，静止时间不得为负，采样偏移须在采样周期内</translation>
    </message>
</context>
<context>
    <name>ChainDynamics</name>
    <message>
        <location filename="../core/model/ChainDynamics.cpp" line="+48"/>
        <source>%1 has %2 moving joints: a chain needs 1 to %3</source>
        <translation>%1 有 %2 个可动关节：运动链需要 1 到 %3 个</translation>
    </message>
</context>
<context>
    <name>ChainModel</name>
    <message>
        <location filename="../core/model/ChainParameterInfo.cpp" line="+32"/>
        <source>link %1 (%2)</source>
        <translation>连杆 %1（%2）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>mass of link %1</source>
        <translation>连杆 %1 的质量</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>first moment of mass of link %1 along its %2 axis</source>
        <translation>连杆 %1 沿其 %2 轴的质量一阶矩</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>inertia %1 of link %2 about its frame origin</source>
        <translation>连杆 %2 关于其坐标系原点的惯量 %1</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>rotor inertia at joint %1</source>
        <translation>关节 %1 处的转子惯量</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>viscous friction of joint %1</source>
        <translation>关节 %1 的粘性摩擦</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Coulomb friction of joint %1</source>
        <translation>关节 %1 的库仑摩擦</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>torque offset of joint %1</source>
        <translation>关节 %1 的力矩偏置</translation>
    </message>
    <message>
        <location line="-15"/>
        <source>joint %1 (%2)</source>
        <translation>关节 %1（%2）</translation>
    </message>
    <message>
        <location filename="../core/model/ChainModel.cpp" line="+55"/>
        <source>the Coulomb friction&apos;s velocity scale must be positive (it is %1)</source>
        <translation>库仑摩擦的速度尺度必须为正（当前为 %1）</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>a combination led by the %1</source>
        <translation>以%1为首的组合</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 has %2 moving joints, the model %3 has %4</source>
        <translation>%1 有 %2 个可动关节，模型 %3 有 %4 个</translation>
    </message>
</context>
<context>
    <name>Cia402</name>
    <message>
        <location filename="../core/can/Cia402.cpp" line="+34"/>
        <source>Not ready to switch on</source>
        <translation>未准备好接通</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Switch on disabled</source>
        <translation>接通禁止</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Ready to switch on</source>
        <translation>准备接通</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Switched on</source>
        <translation>已接通</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Operation enabled</source>
        <translation>运行使能</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Quick stop active</source>
        <translation>快速停止激活</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Fault reaction active</source>
        <translation>故障反应激活</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Fault</source>
        <translation>故障</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Unknown drive state</source>
        <translation>未知驱动器状态</translation>
    </message>
</context>
<context>
    <name>CommissioningSession</name>
    <message>
        <location filename="../core/session/TrialPlanner.cpp" line="+119"/>
        <source>scenario does not fit the %1 model: it needs %2 parameters and %3 joint limits and gains</source>
        <translation>场景与 %1 模型不符：需要 %2 个参数以及 %3 个关节限值和增益</translation>
    </message>
</context>
<context>
    <name>ControllerLogCsv</name>
    <message>
        <location filename="../core/io/ControllerLogCsv.cpp" line="+56"/>
        <source>&quot;# stopped-by:&quot; says %1; known: %2</source>
        <translation>&quot;# stopped-by:&quot; 的值为 %1；已知值：%2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>nothing</source>
        <translation>空</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1: no &quot;# plan-id:&quot; comment line; the controller copies the plan&apos;s line &quot;# plan-id: %2&quot; into its log</source>
        <translation>%1：没有“# plan-id:”注释行；控制器会把计划中的“# plan-id: %2”行复制到其日志中</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: the log is of plan %2, not of plan %3</source>
        <translation>%1：该日志属于计划 %2，而不是计划 %3</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>sample %1 (t = %2 s) is beyond the plan&apos;s %3 samples, the last at t = %4 s</source>
        <translation>采样点 %1（t = %2 s）超出了计划的 %3 个采样点，最后一个位于 t = %4 s</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>t = %1 s is off the plan&apos;s grid: sample %2 is planned at t = %3 s (+-%4 s); a log holds every sample of the plan, at the plan&apos;s times</source>
        <translation>t = %1 s 不在计划的时间网格上：采样点 %2 计划位于 t = %3 s（+-%4 s）；日志应包含计划的每个采样点，且时刻与计划一致</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>the log ends after %1 of the plan&apos;s %2 samples (t = %3 s of %4 s): the controller stopped the trial at its tracking limit</source>
        <translation>日志在计划的 %2 个采样中的第 %1 个之后结束（t = %3 s，共 %4 s）：控制器在其跟踪误差限值处停止了试验</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the log ends after %1 of the plan&apos;s %2 samples (t = %3 s of %4 s): the trial ended early</source>
        <translation>日志在计划的 %2 个采样点中的 %1 个之后结束（t = %3 s，共 %4 s）：试验提前结束</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&quot;# stopped-by:&quot; in a log of all the plan&apos;s %1 samples: a trial that ran to its end was not stopped</source>
        <translation>包含计划全部 %1 个采样的日志中出现 &quot;# stopped-by:&quot;：运行到结束的试验并未被停止</translation>
    </message>
</context>
<context>
    <name>CsvPlace</name>
    <message>
        <location filename="../core/io/CsvPlace.cpp" line="+21"/>
        <source>%1: line %2, column %3</source>
        <translation>%1：第 %2 行第 %3 列</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1: line %2: %3</source>
        <translation>%1：第 %2 行：%3</translation>
    </message>
</context>
<context>
    <name>EmcyConsumer</name>
    <message>
        <location filename="../core/can/EmcyConsumer.cpp" line="+26"/>
        <source>error reset or no error</source>
        <translation>错误复位或无错误</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>generic error</source>
        <translation>一般错误</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+45"/>
        <source>current</source>
        <translation>电流</translation>
    </message>
    <message>
        <location line="-44"/>
        <source>current, device input side</source>
        <translation>电流，设备输入侧</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>current inside the device</source>
        <translation>设备内部电流</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>current, device output side</source>
        <translation>电流，设备输出侧</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>continuous over-current</source>
        <translation>持续过流</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>short circuit or earth leakage</source>
        <translation>短路或接地泄漏</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+40"/>
        <source>voltage</source>
        <translation>电压</translation>
    </message>
    <message>
        <location line="-39"/>
        <source>mains voltage</source>
        <translation>电网电压</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>voltage inside the device</source>
        <translation>设备内部电压</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>DC link over-voltage</source>
        <translation>直流母线过压</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>DC link under-voltage</source>
        <translation>直流母线欠压</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>output voltage</source>
        <translation>输出电压</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+35"/>
        <source>temperature</source>
        <translation>温度</translation>
    </message>
    <message>
        <location line="-34"/>
        <source>ambient temperature</source>
        <translation>环境温度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>device temperature</source>
        <translation>设备温度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>drive excess temperature</source>
        <translation>驱动器过温</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>device hardware</source>
        <translation>设备硬件</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>device software</source>
        <translation>设备软件</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>internal software</source>
        <translation>内部软件</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>user software</source>
        <translation>用户软件</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>data set</source>
        <translation>数据集</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>additional modules</source>
        <translation>附加模块</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sensor</source>
        <translation>传感器</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>incremental sensor 1 fault</source>
        <translation>增量传感器 1 故障</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>monitoring</source>
        <translation>监控</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+23"/>
        <source>communication</source>
        <translation>通信</translation>
    </message>
    <message>
        <location line="-22"/>
        <source>CAN overrun (objects lost)</source>
        <translation>CAN 溢出（对象丢失）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAN in error passive mode</source>
        <translation>CAN 处于错误被动模式</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>life guard or heartbeat error</source>
        <translation>节点保护或心跳错误</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>recovered from bus off</source>
        <translation>已从总线关闭恢复</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAN-ID collision</source>
        <translation>CAN-ID 冲突</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>protocol error</source>
        <translation>协议错误</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PDO not processed due to length error</source>
        <translation>因长度错误未处理 PDO</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PDO length exceeded</source>
        <translation>超出 PDO 长度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unexpected SYNC data length</source>
        <translation>意外的 SYNC 数据长度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RPDO timeout</source>
        <translation>RPDO 超时</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>positioning controller</source>
        <translation>位置控制器</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>following error</source>
        <translation>跟随误差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>external error</source>
        <translation>外部错误</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>additional functions</source>
        <translation>附加功能</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>device specific</source>
        <translation>设备特定</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>generic</source>
        <translation>一般</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>device profile</source>
        <translation>设备行规</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>reserved</source>
        <translation>保留</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>manufacturer</source>
        <translation>制造商特定</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>unknown error code</source>
        <translation>未知错误代码</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>no error</source>
        <translation>无错误</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Node %1 emergency %2: %3; error register %4: %5; manufacturer data %6</source>
        <translation>节点 %1 紧急报文（EMCY）%2：%3；错误寄存器 %4：%5；制造商数据 %6</translation>
    </message>
</context>
<context>
    <name>EstimateConsistency</name>
    <message>
        <location filename="../core/session/EstimateConsistency.cpp" line="+148"/>
        <source>not physically consistent</source>
        <translation>物理不一致</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>physically consistent (every link a real body) but not plausible</source>
        <translation>物理一致（每个连杆都是真实刚体），但不合理</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>physically consistent and plausible: every link a real body that a robot&apos;s link could be</source>
        <translation>物理一致且合理：每个连杆都是可以作为机器人连杆的真实刚体</translation>
    </message>
</context>
<context>
    <name>FileLoop</name>
    <message>
        <location filename="../core/service/FileLoop.cpp" line="+35"/>
        <source>unknown robot model &quot;%1&quot;</source>
        <translation>未知的机器人模型“%1”</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>cannot create the folder %1</source>
        <translation>无法创建文件夹 %1</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>the history %1 is of robot %2 (%3 joints, %4 parameters), the scenario&apos;s robot is %5 (%6 joints, %7 parameters)</source>
        <translation>历史 %1 属于机器人 %2（%3 个关节，%4 个参数），而场景的机器人是 %5（%6 个关节，%7 个参数）</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>the history %1 was made by the arm&apos;s learning loop (a scenario without a payload section); the scenario learns a payload: give another --history for the payload&apos;s loop</source>
        <translation>历史 %1 由机械臂的学习循环生成（场景没有 payload 部分）；而此场景学习负载：请为负载的循环给出另一个 --history</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the history %1 learns the payload on %2 (a scenario with a payload section); the scenario learns the arm: give another --history for the arm&apos;s loop</source>
        <translation>历史 %1 学习 %2 上的负载（场景带 payload 部分）；而此场景学习机械臂：请为机械臂的循环给出另一个 --history</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the history %1 learns with the law %2, the scenario with %3: a history keeps its law (start a new history for another)</source>
        <translation>历史 %1 使用学习律 %2，而场景使用 %3：一个历史始终保持其学习律（如需其他学习律，请新建一个历史）</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>trial %1: check passed, the trial may run.</source>
        <translation>试验 %1：检查通过，可以运行。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>trial %1 refused: %2</source>
        <translation>试验 %1 被拒绝：%2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>feedforward built with: %1</source>
        <translation>前馈基于：%1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>planned motion: %1 s, %2 s with rests, %3 samples of %4 s</source>
        <translation>规划运动：%1 s，含静止 %2 s，%3 个采样点，采样周期 %4 s</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>closed loop: estimate not physical (mass matrix not positive definite)</source>
        <translation>闭环：估计不符合物理（质量矩阵非正定）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>closed loop: stable, max |z| = %1, decay rate %2 1/s</source>
        <translation>闭环：稳定，max |z| = %1，衰减率 %2 1/s</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>closed loop: UNSTABLE, max |z| = %1 at t = %2 s (growth %3 1/s)</source>
        <translation>闭环：不稳定，max |z| = %1，t = %2 s（增长 %3 1/s）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>joint   peak [N m]  limit [N m]     use</source>
        <translation> 关节   峰值 [N m]   限值 [N m]    占用</translation>
    </message>
    <message>
        <location filename="../core/service/FileLoopParts.cpp" line="+78"/>
        <source>%1: plan %2 is not the plan %3 that trial %4 of the history ran</source>
        <translation>%1：计划 %2 不是历史中试验 %4 所运行的计划 %3</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location line="+70"/>
        <source>%1 holds no learning history (no %2): plan the trial with `learnid-cli plan` into this history, or give its --history</source>
        <translation>%1 中没有学习历史（没有 %2）：请用 `learnid-cli plan` 将试验规划到此历史中，或给出其 --history</translation>
    </message>
    <message>
        <location line="-56"/>
        <source>%1: no &quot;# plan-id:&quot; comment line; the controller copies the plan&apos;s &quot;# plan-id:&quot; line into its log</source>
        <translation>%1：没有“# plan-id:”注释行；控制器会把计划中的“# plan-id:”行复制到其日志中</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 ran plan %2, %3 plan %4: the logs of one learning step are of one plan</source>
        <translation>%1 运行的是计划 %2，%3 运行的是计划 %4：同一学习步骤的日志必须属于同一个计划</translation>
    </message>
    <message>
        <location filename="../core/service/FileLoopLearn.cpp" line="+42"/>
        <source>the scenario runs every trial %1 times (repetitions): give one --trial-log per run, %2 given</source>
        <translation>场景中每次试验运行 %1 次（repetitions）：请为每次运行给出一个 --trial-log，实际给出了 %2 个</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 was made with another estimate than the history&apos;s newest (estimate %2): plan the next trial again</source>
        <translation>%1 所用的估计不是历史中最新的估计（估计 %2）：请重新规划下一次试验</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1: %2; nothing learned</source>
        <translation>%1：%2；未学习任何内容</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>the history %1 does not replay: trial %2: %3</source>
        <translation>历史 %1 无法回放：试验 %2：%3</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1 is not the estimate %2 that the history&apos;s trials give with this scenario: is its estimator the history&apos;s?</source>
        <translation>%1 不是历史中的试验在此场景下得到的估计 %2：场景的估计器是否与历史的一致？</translation>
    </message>
    <message>
        <location filename="../core/service/FileLoopPlan.cpp" line="+31"/>
        <source>initial estimate of a learning loop through files</source>
        <translation>基于文件的学习循环的初始估计</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>--estimate: the history %1 has learned from %2 trials; its next trial runs with its newest estimate (leave out --estimate, or give another --history to start a new history)</source>
        <translation>--estimate：历史 %1 已从 %2 次试验中学习；其下一次试验使用其最新估计（请去掉 --estimate，或给出另一个 --history 以开始新的历史）</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>estimate %1 of %2</source>
        <translation>估计 %1（%2）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the scenario&apos;s initial estimate</source>
        <translation>场景的初始估计</translation>
    </message>
    <message>
        <location filename="../core/service/FileLoopPayload.cpp" line="+39"/>
        <source>the history %1 learns the payload on %2, the scenario&apos;s payload.link is %3: a history keeps its link (give another --history for another)</source>
        <translation>历史 %1 学习 %2 上的负载，而场景的 payload.link 为 %3：历史保持其连杆不变（换连杆请给出另一个 --history）</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>the history %1 does not replay: %2</source>
        <translation>历史 %1 无法回放：%2</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>the arm held fixed and the payload learned from the trials up to trial %1: estimate %2 of a payload&apos;s learning loop through files</source>
        <translation>固定的机械臂与从截至试验 %1 的各次试验学得的负载：通过文件进行的负载学习循环的估计 %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the arm held fixed and the payload&apos;s prior: estimate %1 of a payload&apos;s learning loop through files</source>
        <translation>固定的机械臂与负载的先验：通过文件进行的负载学习循环的估计 %1</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>%1 holds another arm model than the scenario&apos;s robot.initialParameters: a history keeps the arm it learns the payload on</source>
        <translation>%1 中的机械臂模型与场景的 robot.initialParameters 不同：历史保持其学习负载时所用的机械臂不变</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 holds another payload prior than the scenario&apos;s payload section: a history keeps its prior</source>
        <translation>%1 中的负载先验与场景的 payload 部分不同：历史保持其先验不变</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 is not the payload estimate %2 that the history&apos;s trials give with this scenario: are its payload section and estimator the history&apos;s?</source>
        <translation>%1 不是历史中的试验在此场景下得到的负载估计 %2：场景的 payload 部分和估计器是否与历史的一致？</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>the path determines %1 of the payload&apos;s 10 parameters on %2</source>
        <translation>路径确定 %2 上负载 10 个参数中的 %1 个</translation>
    </message>
    <message>
        <location filename="../core/service/FileLoopPayloadLearn.cpp" line="+33"/>
        <source>a payload&apos;s learning loop runs every trial once (estimator.repetitions does not apply to it): give one --trial-log, %1 given</source>
        <translation>负载的学习循环每次试验只运行一次（estimator.repetitions 对其不适用）：请给出一个 --trial-log，实际给出 %1 个</translation>
    </message>
    <message>
        <location filename="../core/service/FileLoopPayloadPlan.cpp" line="+23"/>
        <source>the arm&apos;s model held fixed (robot.initialParameters) alone: trial %1 is a baseline trial (payload.baselineTrials), run it WITHOUT the payload mounted</source>
        <translation>仅固定的机械臂模型（robot.initialParameters）：试验 %1 是基线试验（payload.baselineTrials），请在未安装负载的情况下运行</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the arm&apos;s model held fixed (robot.initialParameters) and the payload learned from the trials up to trial %1 (estimate %2 of %3)</source>
        <translation>固定的机械臂模型（robot.initialParameters）和从截至试验 %1 的各次试验学得的负载（%3 中的估计 %2）</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the arm&apos;s model held fixed (robot.initialParameters) and the payload&apos;s prior (payload section)</source>
        <translation>固定的机械臂模型（robot.initialParameters）和负载的先验（payload 部分）</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>--estimate: a scenario with a payload section plans with the arm&apos;s model it holds fixed (robot.initialParameters) and the payload its history has learned, the prior (payload section) first: leave out --estimate</source>
        <translation>--estimate：带 payload 部分的场景使用其固定的机械臂模型（robot.initialParameters）和其历史已学得的负载（最初为 payload 部分的先验）进行规划：请去掉 --estimate</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>%1 (give another --history to start anew)</source>
        <translation>%1（请给出另一个 --history 以重新开始）</translation>
    </message>
</context>
<context>
    <name>JointPath</name>
    <message>
        <location filename="../core/motion/JointPath.cpp" line="+38"/>
        <source>waypoint path: %1 waypoints; a path needs at least 2</source>
        <translation>路点路径：%1 个路点；路径至少需要 2 个</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>waypoint path: waypoint 0 has no joints</source>
        <translation>路点路径：路点 0 没有关节</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>waypoint path: waypoint %1 has %2 joints, waypoint 0 has %3</source>
        <translation>路点路径：路点 %1 有 %2 个关节，路点 0 有 %3 个</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>waypoint path: waypoint %1: joint %2 is %3, not a finite angle</source>
        <translation>路点路径：路点 %1：关节 %2 为 %3，不是有限角度</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>waypoint path: waypoints %1 and %2 are equal or too close to tell apart (largest joint difference %3 rad); the path stops at every waypoint already, remove the repeat</source>
        <translation>路点路径：路点 %1 和 %2 相同或过于接近而无法区分（最大关节差 %3 rad）；路径本来就会在每个路点停下，请删除重复的路点</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>recorded path: %1 sample times but %2 samples of the joints</source>
        <translation>记录的路径：%1 个采样时刻，但关节有 %2 个采样点</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>recorded path: %1 samples; a path needs at least 4</source>
        <translation>记录的路径：%1 个采样点；路径至少需要 4 个</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>recorded path: the samples have no joints</source>
        <translation>记录的路径：采样点不含关节</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>recorded path: sample %1: the time is %2, not a finite number</source>
        <translation>记录的路径：采样点 %1：时间为 %2，不是有限数</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>recorded path: sample %1: the time %2 s does not increase from sample %3 (%4 s)</source>
        <translation>记录的路径：采样点 %1：时间 %2 s 未比采样点 %3（%4 s）增大</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>recorded path: sample %1: joint %2 is %3, not a finite angle</source>
        <translation>记录的路径：采样点 %1：关节 %2 为 %3，不是有限角度</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>recorded path: the sample times are too close to fit a spline</source>
        <translation>记录的路径：采样时刻过于接近，无法拟合样条</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>joint path: the duration must be positive and finite, the time finite, and the state have %1 joints</source>
        <translation>关节路径：持续时间必须为正且有限，时间必须有限，状态必须有 %1 个关节</translation>
    </message>
</context>
<context>
    <name>JsonReader</name>
    <message>
        <location filename="../core/io/JsonReader.cpp" line="+90"/>
        <source>%1 (beyond the range of a double)</source>
        <translation>%1（超出 double 的范围）</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+45"/>
        <source>an array</source>
        <translation>数组</translation>
    </message>
    <message>
        <location line="-43"/>
        <source>an object</source>
        <translation>对象</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>nothing</source>
        <translation>空</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>an integer from %1 to %2</source>
        <translation>%1 到 %2 之间的整数</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: the file is empty; expected a JSON object</source>
        <translation>%1：文件为空；应为 JSON 对象</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1: invalid JSON at line %2, column %3 (byte offset %4): %5</source>
        <translation>%1：第 %2 行第 %3 列（字节偏移 %4）处 JSON 无效：%5</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1: the top level must be a JSON object, got %2</source>
        <translation>%1：顶层必须是 JSON 对象，实际为 %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>a single value</source>
        <translation>单个值</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>must be a finite number, got %1, which is beyond the range of a double</source>
        <translation>必须是有限数，实际为 %1，超出 double 的范围</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>must be a number, got %1</source>
        <translation>必须是数字，实际为 %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>must be a finite number, got %1</source>
        <translation>必须是有限数，实际为 %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+32"/>
        <source>must be %1, got %2</source>
        <translation>必须是%1，实际为 %2</translation>
    </message>
    <message>
        <location line="-15"/>
        <source>must be a string, got %1</source>
        <translation>必须是字符串，实际为 %1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 or %2</source>
        <translation>%1或%2</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>must be true or false, got %1</source>
        <translation>必须是 true 或 false，实际为 %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>must be an array, got %1</source>
        <translation>必须是数组，实际为 %1</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>must be an object, got %1</source>
        <translation>必须是对象，实际为 %1</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>is missing; this key is required</source>
        <translation>缺失；此键为必需项</translation>
    </message>
    <message>
        <location line="+51"/>
        <source>unknown key; allowed here: %1</source>
        <translation>未知的键；此处允许：%1</translation>
    </message>
</context>
<context>
    <name>LearningLaw</name>
    <message>
        <location filename="../core/identify/ImprovedLaw.cpp" line="+61"/>
        <location filename="../core/identify/PaperLaw.cpp" line="+44"/>
        <source>trial record has only %1 samples to learn from</source>
        <translation>试验记录只有 %1 个可用于学习的采样</translation>
    </message>
    <message>
        <location line="+87"/>
        <location filename="../core/identify/PaperLaw.cpp" line="-26"/>
        <source>no completed trial to learn from</source>
        <translation>没有可供学习的已完成试验</translation>
    </message>
    <message>
        <location filename="../core/identify/LearningLaw.cpp" line="+87"/>
        <source>trial record does not match its plan: %1 of %2 samples, %3 joints recorded for a %4-joint model</source>
        <translation>试验记录与其计划不符：%2 个采样点中记录了 %1 个，%4 关节模型记录了 %3 个关节</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>trial record has only %1 samples</source>
        <translation>试验记录只有 %1 个采样点</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>trial record has a non-finite %1 at sample %2, joint %3</source>
        <translation>试验记录在采样点 %2、关节 %3 处有非有限的%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>torque</source>
        <translation>力矩</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>angle</source>
        <translation>角度</translation>
    </message>
</context>
<context>
    <name>LinkVerdictTable</name>
    <message>
        <location filename="../core/session/LinkVerdictTable.cpp" line="+25"/>
        <source>yes</source>
        <translation>是</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>no</source>
        <translation>否</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Per link: physically consistent (a real body), and plausible (a body a robot&apos;s link could be: its smallest principal moment of inertia about the centre of mass I1 at least %1 % of the CAD link&apos;s, (I1 + I2) / I3 at least %2, the centre of mass inside the link&apos;s bounding volume).</source>
        <translation>每个连杆：物理一致（真实刚体）且合理（可以作为机器人连杆的刚体：其绕质心的最小主惯性矩 I1 至少为 CAD 连杆的 %1 %，(I1 + I2) / I3 至少为 %2，质心位于连杆包围体之内）。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>link</source>
        <translation>连杆</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>I1 [kg m^2]</source>
        <translation>I1 [kg m^2]</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>CAD I1 [kg m^2]</source>
        <translation>CAD I1 [kg m^2]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>(I1 + I2) / I3</source>
        <translation>(I1 + I2) / I3</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>CoM in volume</source>
        <translation>质心在包围体内</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>consistent</source>
        <translation>一致</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>plausible</source>
        <translation>合理</translation>
    </message>
</context>
<context>
    <name>LogFit</name>
    <message>
        <location filename="../core/identify/LogFit.cpp" line="+141"/>
        <source>%1 has %2 joints, the robot %3</source>
        <translation>%1 有 %2 个关节，机器人有 %3 个</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: the filtered signals are not finite</source>
        <translation>%1：滤波后的信号不是有限值</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>no samples to fit</source>
        <translation>没有可用于拟合的采样点</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the prior share must lie between 0 and 1</source>
        <translation>先验比例必须在 0 到 1 之间</translation>
    </message>
    <message>
        <location line="+98"/>
        <source>%1 does not fit the robot&apos;s joints or parameters</source>
        <translation>%1 与机器人的关节或参数不符</translation>
    </message>
</context>
<context>
    <name>LogIdentification</name>
    <message>
        <location filename="../core/service/LogIdentification.cpp" line="+81"/>
        <source>identification cancelled; nothing was produced</source>
        <translation>辨识已取消；未生成任何结果</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>the robot &apos;%1&apos; is neither a URDF file nor a built-in robot (%2)</source>
        <translation>机器人 &apos;%1&apos; 既不是 URDF 文件，也不是内置机器人（%2）</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>built-in %1</source>
        <translation>内置机器人 %1</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>no log to identify from: add a training log</source>
        <translation>没有可用于辨识的日志：请添加一个训练日志</translation>
    </message>
    <message>
        <location filename="../core/service/LogIdentificationExport.cpp" line="+26"/>
        <source>%1 (%2), identified from the logs %3</source>
        <translation>%1（%2），由日志 %3 辨识</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>the controller gains the parameter file records are for %1 joints, the robot has %2</source>
        <translation>参数文件记录的控制器增益适用于 %1 个关节，机器人有 %2 个</translation>
    </message>
</context>
<context>
    <name>LogIdentificationSummary</name>
    <message>
        <location filename="../core/service/LogIdentificationSummary.cpp" line="+21"/>
        <source>Of the %1 standard parameters, any data could determine at most %2 combinations (the base parameters); these logs determine all %2 (condition %3).</source>
        <translation>在 %1 个标准参数中，任何数据至多能确定 %2 个组合（即基参数）；这些日志确定了全部 %2 个（条件数 %3）。</translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>Of the %1 standard parameters, any data could determine at most %2 combinations (the base parameters); these logs determine %3 of those %2 directions (condition %4), the other %n stay near the URDF&apos;s values.</source>
        <translation>
            <numerusform>在 %1 个标准参数中，任何数据至多能确定 %2 个组合（即基参数）；这些日志确定了这 %2 个方向中的 %3 个（条件数 %4），其余 %n 个保持在 URDF 值附近。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+12"/>
        <source>%n of the %1 base parameters are mostly undetermined by these logs (less than half determined) and kept near the URDF&apos;s values: %2.</source>
        <translation>
            <numerusform>%1 个基参数中有 %n 个基本未被这些日志确定（确定的部分不到一半），保持在 URDF 值附近：%2。</numerusform>
        </translation>
    </message>
    <message>
        <location line="+6"/>
        <source>None of the %1 base parameters is mostly undetermined by these logs.</source>
        <translation>%1 个基参数中没有一个基本未被这些日志确定。</translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>None of the %1 base parameters is mostly undetermined by these logs: the %n direction(s) they miss are shared among several.</source>
        <translation>
            <numerusform>%1 个基参数中没有一个基本未被这些日志确定：日志未确定的 %n 个方向分散在多个基参数上。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+10"/>
        <source>%n stale row(s) (values repeated under a new time stamp) treated as missing</source>
        <translation>
            <numerusform>%n 行过时数据（在新时间戳下重复了之前的值）按缺失处理</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>%n row(s) written twice (the same time stamp and values) dropped</source>
        <translation>
            <numerusform>%n 行重复写入的数据（时间戳和值都相同）已丢弃</numerusform>
        </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: %2.</source>
        <translation>%1：%2。</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 (URDF robot &quot;%2&quot;)</source>
        <translation>%1（URDF 机器人“%2”）</translation>
    </message>
    <message numerus="yes">
        <location line="+8"/>
        <source>%1 in %2, %n moving joint(s).</source>
        <translation>
            <numerusform>%1，位于 %2，%n 个可动关节。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%1 (built-in), %n moving joint(s).</source>
        <translation>
            <numerusform>%1（内置），%n 个可动关节。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>Fitted to %n log(s), %1 samples; %2.</source>
        <translation>
            <numerusform>用 %n 个日志、%1 个采样点拟合；%2。</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the consistent fit converged</source>
        <translation>一致拟合已收敛</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the consistent fit stopped at its step limit</source>
        <translation>一致拟合在步数上限处停止</translation>
    </message>
</context>
<context>
    <name>LogIdentificationText</name>
    <message>
        <location filename="../ui/LogIdentificationText.cpp" line="+56"/>
        <source>Reading the robot %1…</source>
        <translation>正在读取机器人 %1…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reading training log %1 of %2: %3…</source>
        <translation>正在读取训练日志 %1/%2：%3…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reading validation log %1 of %2: %3…</source>
        <translation>正在读取验证日志 %1/%2：%3…</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>Fitting the parameters to %n log(s)…</source>
        <translation>
            <numerusform>正在用 %n 个日志拟合参数…</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Predicting validation log %1 of %2: %3…</source>
        <translation>正在预测验证日志 %1/%2：%3…</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>&lt;p&gt;&lt;b&gt;Identified parameters:&lt;/b&gt; &lt;span style=&quot;color:%1&quot;&gt;%2&lt;/span&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;识别参数：&lt;/b&gt;&lt;span style=&quot;color:%1&quot;&gt;%2&lt;/span&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&lt;p&gt;&lt;b&gt;Training residual&lt;/b&gt;, RMS per joint [N m]: %1&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;训练残差&lt;/b&gt;，各关节 RMS [N m]：%1&lt;/p&gt;</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&lt;p style=&quot;color:#8a5300&quot;&gt;&lt;b&gt;Warning:&lt;/b&gt; the URDF as a real robot: %1&lt;/p&gt;</source>
        <translation>&lt;p style=&quot;color:#8a5300&quot;&gt;&lt;b&gt;警告：&lt;/b&gt;该 URDF 作为真实机器人：%1&lt;/p&gt;</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Identified; no validation log. Accept the result to export it.</source>
        <translation>已辨识；没有验证日志。接受结果后即可导出。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Identified: on %1 the torque error is %2 % of the measured torque (URDF as given: %3 %). Accept the result to export it.</source>
        <translation>已辨识：在 %1 上，力矩误差为测量力矩的 %2 %（给定的 URDF：%3 %）。接受结果后即可导出。</translation>
    </message>
</context>
<context>
    <name>LogSignals</name>
    <message>
        <location filename="../core/identify/LogSignals.cpp" line="+57"/>
        <source>the log filter needs positive bandwidths, a stride of 1 or more and a torque sensor lag of 0 s or more</source>
        <translation>日志滤波器需要正的带宽、不小于 1 的步长和不小于 0 s 的力矩传感器滞后</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: the log has no measured velocities (dq columns) to use</source>
        <translation>%1：日志中没有可用的测量速度（dq 列）</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: %2 s of data is too short: the filter (bandwidth %3 rad/s) needs %4 s at each end to settle, and some data between</source>
        <translation>%1：%2 s 的数据太短：滤波器（带宽 %3 rad/s）在两端各需要 %4 s 来稳定，中间还需要一些数据</translation>
    </message>
</context>
<context>
    <name>LoopHistory</name>
    <message>
        <location filename="../core/io/LoopHistory.cpp" line="+33"/>
        <source>must be a plain file name in the history folder (letters, digits, &apos;.&apos;, &apos;_&apos;, &apos;-&apos;), got &quot;%1&quot;</source>
        <translation>必须是历史文件夹中的简单文件名（字母、数字、&apos;.&apos;、&apos;_&apos;、&apos;-&apos;），实际为“%1”</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>must be 64 lower-case hex digits (SHA-256), got &quot;%1&quot;</source>
        <translation>必须是 64 位小写十六进制数字（SHA-256），实际为“%1”</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+2"/>
        <location line="+66"/>
        <source>must not be empty</source>
        <translation>不得为空</translation>
    </message>
    <message>
        <location line="-64"/>
        <source>one more than trials, the initial estimate first</source>
        <translation>比试验多一个，初始估计在最前</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>one per joint</source>
        <translation>每个关节一个</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>must name at least one log</source>
        <translation>必须至少列出一个日志</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>is missing; this is not a learnid history index</source>
        <translation>缺失；这不是 learnid 历史索引</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>this version of learnid reads &quot;%1&quot;, got %2</source>
        <translation>此版本的 learnid 读取“%1”，实际为 %2</translation>
    </message>
    <message>
        <location line="+92"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
</context>
<context>
    <name>ManufacturerObjects</name>
    <message>
        <location filename="../core/can/ManufacturerObjects.cpp" line="+121"/>
        <source>No node to write the parameters to.</source>
        <translation>没有可写入参数的节点。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A parameter set holds 1 to %1 parameters, not %2.</source>
        <translation>参数组包含 1 到 %1 个参数，而不是 %2 个。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 is not a valid CANopen node id (1 to 127).</source>
        <translation>%1 不是有效的 CANopen 节点 ID（1 到 127）。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Node %1 is listed twice.</source>
        <translation>节点 %1 被列出两次。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Parameter %1 (%2) cannot be sent as REAL32.</source>
        <translation>参数 %1（%2）无法以 REAL32 发送。</translation>
    </message>
</context>
<context>
    <name>MeshBounds</name>
    <message>
        <location filename="../core/model/MeshBounds.cpp" line="+67"/>
        <source>not readable as a mesh (%1)</source>
        <translation>无法作为网格读取（%1）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>has no vertices</source>
        <translation>没有顶点</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>names no package</source>
        <translation>未指明软件包</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>package &quot;%1&quot; not found (ROS_PACKAGE_PATH, the URDF&apos;s folder)</source>
        <translation>未找到软件包“%1”（ROS_PACKAGE_PATH、URDF 所在文件夹）</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>a relative name without the URDF&apos;s folder</source>
        <translation>相对名称，但没有 URDF 所在文件夹</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+11"/>
        <source>no such file</source>
        <translation>没有该文件</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>empty</source>
        <translation>空文件</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>larger than 256 MB, not read</source>
        <translation>大于 256 MB，未读取</translation>
    </message>
</context>
<context>
    <name>ModelCheck</name>
    <message>
        <location filename="../core/model/ModelCheck.cpp" line="+27"/>
        <source>link %1 (%2)</source>
        <translation>连杆 %1（%2）</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>joint %1 (%2)</source>
        <translation>关节 %1（%2）</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1: its mass is %2 kg: not a real body</source>
        <translation>%1：其质量为 %2 kg：不是真实刚体</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: no mass distribution has its inertia (its pseudo-inertia has the negative eigenvalue %2): not a real body</source>
        <translation>%1：没有任何质量分布具有其惯性（其伪惯性矩阵有负特征值 %2）：不是真实刚体</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1: %2 is %3, negative: friction and rotor inertia take energy, they do not give it</source>
        <translation>%1：%2 为 %3，是负值：摩擦和转子惯量只消耗能量，不会提供能量</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: %2 is %3, between 0 and %4: the underflow of a positive parametrisation where 0 is meant</source>
        <translation>%1：%2 为 %3，介于 0 和 %4 之间：这是本应为 0 的正参数化的下溢</translation>
    </message>
</context>
<context>
    <name>ModelFactory</name>
    <message>
        <location filename="../core/model/ModelFactory.cpp" line="+71"/>
        <source>robot.urdf.file: the &quot;urdf&quot; model needs a URDF file</source>
        <translation>robot.urdf.file：“urdf”模型需要 URDF 文件</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: cannot read the URDF: %2</source>
        <translation>%1：无法读取 URDF：%2</translation>
    </message>
</context>
<context>
    <name>Nmt</name>
    <message>
        <location filename="../core/can/Nmt.cpp" line="+14"/>
        <source>boot-up</source>
        <translation>启动（boot-up）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>stopped</source>
        <translation>停止（stopped）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>operational</source>
        <translation>运行（operational）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>pre-operational</source>
        <translation>预运行（pre-operational）</translation>
    </message>
</context>
<context>
    <name>ObservableUpdate</name>
    <message>
        <location filename="../core/identify/GramBlock.cpp" line="+13"/>
        <source>least squares sizes do not match: %1 x %2 regressor, %3 targets, %4 joints, %5 parameters</source>
        <translation>最小二乘维度不匹配：%1 x %2 回归矩阵，%3 个目标值，%4 个关节，%5 个参数</translation>
    </message>
    <message>
        <location filename="../core/identify/ObservableUpdate.cpp" line="+20"/>
        <source>the regressor or the torque contains non-finite values</source>
        <translation>回归矩阵或力矩包含非有限值</translation>
    </message>
</context>
<context>
    <name>OutputPath</name>
    <message>
        <location filename="../core/io/OutputPath.cpp" line="+23"/>
        <source>%1: no path given</source>
        <translation>%1：未给出路径</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1: %2 is relative, and the folder it is taken from, %3, does not exist or is not a folder</source>
        <translation>%1：%2 是相对路径，而其基准文件夹 %3 不存在或不是文件夹</translation>
    </message>
</context>
<context>
    <name>ParameterFile</name>
    <message>
        <location filename="../core/io/ParameterDcf.cpp" line="+35"/>
        <source>does not fit a REAL32 object entry, got %1</source>
        <translation>无法放入 REAL32 对象条目，实际为 %1</translation>
    </message>
    <message>
        <location line="+109"/>
        <source>the payload object is written in part</source>
        <translation>负载对象只被部分写入</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>DCF fragment: joint %1 does not exist; the robot has %2 joints</source>
        <translation>DCF 片段：关节 %1 不存在；机器人有 %2 个关节</translation>
    </message>
    <message>
        <location filename="../core/io/ParameterFile.cpp" line="+179"/>
        <source>must be given for every parameter or for none</source>
        <translation>必须为每个参数都给出，或都不给出</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>must be &quot;%1&quot; for determined %2, got &quot;%3&quot;</source>
        <translation>determined 为 %2 时必须是“%1”，实际为“%3”</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>must be an object index written as &quot;0x&quot; and four hex digits, got &quot;%1&quot;</source>
        <translation>必须是以“0x”加四位十六进制数字写成的对象索引，实际为“%1”</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>must be the bytes written as pairs of hex digits, got &quot;%1&quot;</source>
        <translation>必须是以成对十六进制数字表示的写入字节，实际为“%1”</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>must be a date and time as in 2024-05-01T12:00:00.000Z, got &quot;%1&quot;</source>
        <translation>必须是形如 2024-05-01T12:00:00.000Z 的日期时间，实际为“%1”</translation>
    </message>
    <message>
        <location line="+74"/>
        <source>is missing; this is not a learnid parameter file</source>
        <translation>缺失；这不是 learnid 参数文件</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>this version of learnid reads &quot;%1&quot; and &quot;%2&quot;, got %3</source>
        <translation>此版本的 learnid 读取“%1”和“%2”，实际为 %3</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>is missing; this key is required</source>
        <translation>缺失；此键为必需项</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>does not match the content: the file was changed after learnid wrote it, or is damaged</source>
        <translation>与内容不符：文件在 learnid 写入后被修改，或已损坏</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../core/io/ParameterFileValidation.cpp" line="+78"/>
        <source>unknown model &quot;%1&quot;; known models: %2</source>
        <translation>未知模型“%1”；已知模型：%2</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>one per joint of %1</source>
        <translation>%1 的每个关节一个</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>node %1 is given to two joints</source>
        <translation>节点 %1 被分配给两个关节</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>must be a valid date and time</source>
        <translation>必须是有效的日期时间</translation>
    </message>
    <message>
        <location line="-73"/>
        <location line="+75"/>
        <location line="+15"/>
        <location line="+5"/>
        <source>must not be empty</source>
        <translation>不得为空</translation>
    </message>
    <message>
        <location line="-105"/>
        <source>one per standard parameter</source>
        <translation>每个标准参数一个</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>determined shares, %1</source>
        <translation>确定份额，%1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>must be a share from 0 to 1 or null, got %1</source>
        <translation>必须是 0 到 1 之间的份额或 null，实际为 %1</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>must give each joint&apos;s node when the file records no controller</source>
        <translation>文件未记录控制器时必须给出每个关节的节点</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>unknown learning law &quot;%1&quot;; known laws: %2</source>
        <translation>未知学习律“%1”；已知学习律：%2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>must be a trial index or -1 (not recorded), got %1</source>
        <translation>必须是试验索引或 -1（未记录），实际为 %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>one per parameter of %1</source>
        <translation>%1 的每个参数一个</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>must be &quot;%1&quot; (parameter %2 of %3), got &quot;%4&quot;</source>
        <translation>必须是“%1”（%3 的参数 %2），实际为“%4”</translation>
    </message>
    <message>
        <location line="-105"/>
        <location line="+111"/>
        <source>values, %1</source>
        <translation>数值，%1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>standard deviations, %1</source>
        <translation>标准差，%1</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>must name the CANopen data type</source>
        <translation>必须指明 CANopen 数据类型</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>must hold the bytes written</source>
        <translation>必须包含写入的字节</translation>
    </message>
    <message>
        <location filename="../core/io/ParameterFilePayload.cpp" line="+49"/>
        <location line="+49"/>
        <source>the payload&apos;s values</source>
        <translation>负载的值</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>must be &quot;data&quot; (identified) or &quot;prior&quot; (kept at the prior), got &quot;%1&quot;</source>
        <translation>必须是“data”（已辨识）或“prior”（保留先验），实际为“%1”</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>must name the link the payload is fixed to</source>
        <translation>必须给出负载所固定的连杆</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the model %1 has no links to fix a payload to; a payload needs a URDF robot</source>
        <translation>模型 %1 没有可固定负载的连杆；负载需要 URDF 机器人</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>is not a real body&apos;s inertia with this mass and centre of mass (its pseudo-inertia has the negative eigenvalue %1)</source>
        <translation>不是具有该质量和质心的真实刚体的惯性（其伪惯性矩阵有负特征值 %1）</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>must be null for a value kept at the prior (source[%1] is &quot;prior&quot;), got %2</source>
        <translation>对保留先验的值必须为 null（source[%1] 为“prior”），实际为 %2</translation>
    </message>
</context>
<context>
    <name>PathCsv</name>
    <message>
        <location filename="../core/io/PathCsv.cpp" line="+54"/>
        <source>the header must be %1 (the time, then one column per joint); expected %2, got %3</source>
        <translation>表头必须是 %1（先是时间，然后每个关节一列）；应为 %2，实际为 %3</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the header must be %1 (the time, then one column per joint); the joint columns are missing</source>
        <translation>表头必须是 %1（先是时间，然后每个关节一列）；缺少关节列</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the header names the joints q1..q%1; the robot has %2 joints</source>
        <translation>表头列出的关节为 q1..q%1；机器人有 %2 个关节</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>expected %1 fields (%2), got %3</source>
        <translation>应有 %1 个字段（%2），实际为 %3</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>the field is empty; expected a number</source>
        <translation>字段为空；应为数字</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not a number: %1</source>
        <translation>不是数字：%1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the times must increase from sample to sample, got %1 after %2 on line %3</source>
        <translation>时间必须逐个采样点递增，实际在第 %3 行的 %2 之后为 %1</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>the file holds no header line; expected %1</source>
        <translation>文件中没有表头行；应为 %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 samples after the header on line %2; a path needs at least %3</source>
        <translation>第 %2 行的表头之后有 %1 个采样点；路径至少需要 %3 个</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>path CSV: %1 sample times but %2 samples of the joints</source>
        <translation>路径 CSV：%1 个采样时刻，但关节有 %2 个采样点</translation>
    </message>
</context>
<context>
    <name>PathIdentifiability</name>
    <message>
        <location filename="../core/session/PathIdentifiability.cpp" line="+32"/>
        <source>the path observes %1 of %2 parameter directions (condition %3)</source>
        <translation>该路径可观测 %2 个参数方向中的 %1 个（条件数 %3）</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>it cannot see, and the trials keep: %1</source>
        <translation>它无法观测、试验将保持不变的参数：%1</translation>
    </message>
</context>
<context>
    <name>Payload</name>
    <message>
        <location filename="../core/model/Payload.cpp" line="+22"/>
        <source>the payload&apos;s inertial parameters are not finite</source>
        <translation>负载的惯性参数不是有限值</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the payload&apos;s mass must be positive (it is %1 kg)</source>
        <translation>负载质量必须为正（当前为 %1 kg）</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 has no moving link to carry a payload</source>
        <translation>%1 没有可承载负载的运动连杆</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>payload link &apos;%1&apos; is not a moving link of %2 or a link fixed to one (its links: %3)</source>
        <translation>负载连杆“%1”既不是 %2 的运动连杆，也不是固定在运动连杆上的连杆（其连杆：%3）</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>a payload needs the arm&apos;s model</source>
        <translation>负载需要机械臂的模型</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the arm&apos;s parameters for %1 must be %2 finite numbers</source>
        <translation>%1 的机械臂参数必须是 %2 个有限数</translation>
    </message>
</context>
<context>
    <name>PayloadArm</name>
    <message>
        <location filename="../core/service/PayloadArm.cpp" line="+42"/>
        <source>%1: standardParameters: is empty (robot.model %2): the arm&apos;s model for a payload is the whole model as standard parameters, as `learnid-cli identify --export` writes it for a URDF robot</source>
        <translation>%1：standardParameters：为空（robot.model %2）：负载所用的机械臂模型是以标准参数表示的完整模型，即 `learnid-cli identify --export` 为 URDF 机器人写出的形式</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: robot.model is &quot;urdf&quot;: the file does not carry its URDF; give the URDF the arm was identified on with %2</source>
        <translation>%1：robot.model 为“urdf”：文件不包含其 URDF；请用 %2 给出辨识机械臂时所用的 URDF</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: only for a parameter file of robot.model &quot;urdf&quot;; %2 is of the built-in %3, whose URDF is known</source>
        <translation>%1：仅用于 robot.model 为“urdf”的参数文件；%2 属于内置的 %3，其 URDF 已知</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1: standardParameters: has %2 entries, the arm&apos;s model from %3 has %4: the file was not identified on this URDF (or with other base and tip links)</source>
        <translation>%1：standardParameters：有 %2 项，来自 %3 的机械臂模型有 %4 项：该文件不是在此 URDF 上辨识的（或使用了其他基座和末端连杆）</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1: standardParameters[%2].name: is &quot;%3&quot;, the arm&apos;s model from %4 has &quot;%5&quot; there: the file was not identified on this URDF</source>
        <translation>%1：standardParameters[%2].name：为“%3”，来自 %4 的机械臂模型在此处为“%5”：该文件不是在此 URDF 上辨识的</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 holds a payload on %2; it is not part of the arm&apos;s model and is left out</source>
        <translation>%1 包含 %2 上的负载；它不属于机械臂模型，已略去</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>%1: only for a parameter file of robot.model &quot;urdf&quot; given as the arm; %2 is a URDF or a built-in robot</source>
        <translation>%1：仅用于作为机械臂给出的、robot.model 为“urdf”的参数文件；%2 是 URDF 或内置机器人</translation>
    </message>
</context>
<context>
    <name>PayloadBaseline</name>
    <message>
        <location filename="../core/identify/PayloadBaseline.cpp" line="+63"/>
        <source>%1 covers less than %2 % of %3 within a shift of %4 s: a baseline runs the same timed path without the payload</source>
        <translation>在 %4 s 的平移范围内，%1 覆盖 %3 的部分少于 %2 %：基线须在不带负载的情况下运行同一条定时路径</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 (%2 joints, %3 samples of %4 s) is not a baseline of %5 (%6 joints, %7 samples of %8 s): a baseline runs the same timed path without the payload</source>
        <translation>%1（%2 个关节，%3 个采样，周期 %4 s）不是 %5（%6 个关节，%7 个采样，周期 %8 s）的基线：基线须在不带负载的情况下运行同一条定时路径</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1: the filtered signals are not finite</source>
        <translation>%1：滤波后的信号不是有限值</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1 does not follow the path of %2: their joint angles differ by %3 deg RMS (at most %4 deg) after a shift of %5 s</source>
        <translation>%1 没有沿 %2 的路径运动：平移 %5 s 后两者的关节角相差 %3 度 RMS（最多允许 %4 度）</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>the baselines together cover less than %1 % of %2</source>
        <translation>所有基线合起来覆盖 %2 的部分少于 %1 %</translation>
    </message>
</context>
<context>
    <name>PayloadEstimate</name>
    <message>
        <location filename="../core/identify/PayloadEstimate.cpp" line="+61"/>
        <source>the payload&apos;s rows (%1 x %2) and targets (%3) do not match</source>
        <translation>负载的行（%1 x %2）与目标值（%3）不匹配</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the payload&apos;s rows or targets are not finite</source>
        <translation>负载的行或目标值不是有限值</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the variance factor must be positive</source>
        <translation>方差因子必须为正</translation>
    </message>
    <message>
        <location line="+70"/>
        <source>no direction determined: the prior</source>
        <translation>没有确定的方向：采用先验</translation>
    </message>
</context>
<context>
    <name>PayloadExport</name>
    <message>
        <location filename="../core/service/PayloadExport.cpp" line="+80"/>
        <source>%1 (%2) with a payload on %3 identified from the logs %4</source>
        <translation>%1（%2），%3 上的负载由日志 %4 辨识</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>the controller gains the parameter file records are for %1 joints, the robot has %2</source>
        <translation>参数文件记录的控制器增益适用于 %1 个关节，机器人有 %2 个</translation>
    </message>
</context>
<context>
    <name>PayloadFit</name>
    <message>
        <location filename="../core/identify/PayloadFit.cpp" line="+99"/>
        <source>%1 has %2 joints, the robot %3</source>
        <translation>%1 有 %2 个关节，机器人有 %3 个</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: the filtered signals are not finite</source>
        <translation>%1：滤波后的信号不是有限值</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>no samples to fit the payload to</source>
        <translation>没有可用于拟合负载的采样</translation>
    </message>
</context>
<context>
    <name>PayloadIdentification</name>
    <message>
        <location filename="../core/service/PayloadIdentification.cpp" line="+40"/>
        <source>no log to identify the payload from</source>
        <translation>没有用于辨识负载的日志</translation>
    </message>
</context>
<context>
    <name>PayloadObjects</name>
    <message>
        <location filename="../core/can/PayloadObjects.cpp" line="+66"/>
        <source>The payload&apos;s joint %1 is not one of the robot&apos;s joints 1 to %2.</source>
        <translation>负载的关节 %1 不是机器人的关节 1 到 %2 之一。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>A payload has 10 parameters, not %1.</source>
        <translation>负载有 10 个参数，而不是 %1 个。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Payload parameter %1 (%2) cannot be sent as REAL32.</source>
        <translation>负载参数 %1（%2）无法以 REAL32 发送。</translation>
    </message>
</context>
<context>
    <name>PayloadObservability</name>
    <message>
        <location filename="../core/identify/PayloadObservability.cpp" line="+48"/>
        <source>the mass is not seen: the path must hold the payload against gravity in several orientations of %1, or accelerate it</source>
        <translation>质量不可见：路径必须在 %1 的多个姿态下抵抗重力保持负载，或使其加速</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>the centre of mass along the %1 axis of %2 is not seen: the mass and the centre of mass need changes of the wrist&apos;s orientation; tilt the wrist so that this axis turns away from the vertical</source>
        <translation>沿 %2 的 %1 轴的质心不可见：质量和质心需要改变手腕的姿态；倾斜手腕，使该轴偏离竖直方向</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the centre of mass along the %1 axes of %2 is not seen: the mass and the centre of mass need changes of the wrist&apos;s orientation; tilt the wrist so that these axes turn away from the vertical</source>
        <translation>沿 %2 的 %1 轴的质心不可见：质量和质心需要改变手腕的姿态；倾斜手腕，使这些轴偏离竖直方向</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>the inertia %1 is not seen: the full inertia needs rotations of the wrist about several axes, with accelerations</source>
        <translation>惯量 %1 不可见：完整的惯量需要手腕绕多个轴加速转动</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>the payload&apos;s regressor has 10 columns, not %1</source>
        <translation>负载回归矩阵有 10 列，而不是 %1 列</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the share of the strongest direction must lie between 0 and 1</source>
        <translation>最强方向的比例必须在 0 和 1 之间</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the payload&apos;s regressor is not finite</source>
        <translation>负载回归矩阵不是有限值</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>the path must give q, qd and qdd for the %1 joints at every sample</source>
        <translation>路径必须在每个采样点给出 %1 个关节的 q、qd 和 qdd</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the path has no samples</source>
        <translation>路径没有采样</translation>
    </message>
</context>
<context>
    <name>PayloadPathChange</name>
    <message>
        <location filename="../core/session/PayloadPathChange.cpp" line="+55"/>
        <source>moving %1 at waypoint %2 by %3 rad (to %4 rad, inside its limits) would let the trials measure %5</source>
        <translation>将 %1 在路径点 %2 处移动 %3 rad（到 %4 rad，在其限位之内）即可让试验测得 %5</translation>
    </message>
</context>
<context>
    <name>PayloadPrior</name>
    <message>
        <location filename="../core/model/PayloadPrior.cpp" line="+53"/>
        <source>box %1 to %2 m</source>
        <translation>长方体 %1 至 %2 m</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sphere of radius %1 m around %2 m</source>
        <translation>以 %2 m 为中心、半径 %1 m 的球</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1: the payload&apos;s mass must be a positive number of kg, not %2</source>
        <translation>%1：负载质量必须是正的千克数，而不是 %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: the centre of mass must be finite, not %2</source>
        <translation>%1：质心必须是有限值，而不是 %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: the box&apos;s upper corner %2 must lie above its lower corner %3 in x, y and z</source>
        <translation>%1：长方体的上角 %2 必须在 x、y 和 z 上都高于下角 %3</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: the bounding sphere needs a positive radius [m], not %2</source>
        <translation>%1：包围球需要正的半径 [m]，而不是 %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: the prior centre of mass %2 m is not inside the bound (%3): give a bound that contains it</source>
        <translation>%1：先验质心 %2 m 不在边界内（%3）：请给出包含它的边界</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1: the inertia must be finite and symmetric</source>
        <translation>%1：惯量必须是有限且对称的</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: the inertia is not a real body&apos;s (principal moments %2 kg m^2 must be positive and each at most the sum of the others)</source>
        <translation>%1：该惯量不属于真实物体（主惯量 %2 kg m^2 必须为正，且每个不超过其余两者之和）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: a body with this inertia does not fit in the bound (%2)</source>
        <translation>%1：具有该惯量的物体无法放入边界（%2）</translation>
    </message>
</context>
<context>
    <name>PayloadRun</name>
    <message>
        <location filename="../core/service/PayloadRun.cpp" line="+32"/>
        <source>payload: the scenario has no payload section</source>
        <translation>payload：场景没有 payload 部分</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>robot.model: unknown robot model &quot;%1&quot;</source>
        <translation>robot.model：未知的机器人模型“%1”</translation>
    </message>
    <message>
        <location line="+108"/>
        <source>no trial was learned from: the payload is not estimated</source>
        <translation>没有从任何试验中学习：未估计负载</translation>
    </message>
</context>
<context>
    <name>PayloadRunExport</name>
    <message numerus="yes">
        <location filename="../core/service/PayloadRunExport.cpp" line="+41"/>
        <source>%1 with a payload on %2 learned in %n trial(s) with the arm&apos;s model held fixed</source>
        <translation>
            <numerusform>%1，负载位于 %2，在手臂模型保持不变的情况下经 %n 次试验学习</numerusform>
        </translation>
    </message>
    <message>
        <location line="+81"/>
        <source>%1: the folder for the trial CSVs cannot be created</source>
        <translation>%1：无法创建试验 CSV 的文件夹</translation>
    </message>
</context>
<context>
    <name>PayloadSession</name>
    <message>
        <location filename="../core/session/PayloadSession.cpp" line="+24"/>
        <source>payload: only a URDF robot carries a payload (the model is %1)</source>
        <translation>payload：只有 URDF 机器人才能携带负载（模型为 %1）</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>baseline trial %1</source>
        <translation>基线试验 %1</translation>
    </message>
    <message>
        <location line="+101"/>
        <source>trial %1 refused before motion: %2</source>
        <translation>试验 %1 在运动前被拒绝：%2</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>trial %1 did not complete (%2): the payload estimate is unchanged</source>
        <translation>试验 %1 未完成（%2）：负载估计保持不变</translation>
    </message>
    <message>
        <location line="-113"/>
        <source>trial %1</source>
        <translation>试验 %1</translation>
    </message>
    <message>
        <location line="+124"/>
        <source>baseline trial %1 not usable: %2</source>
        <translation>基线试验 %1 不可用：%2</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>the payload fit produced non-finite parameters</source>
        <translation>负载拟合得到了非有限的参数</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>trial %1 stopped at the tracking limit (%2): learned from the %3 s before the stop</source>
        <translation>试验 %1 在跟踪误差限值处停止（%2）：已从停止前的 %3 s 数据中学习</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>; the second stop in a row: the gains do not hold the payload, stiffen them (scenario --print --payload)</source>
        <translation>；连续第二次停止：增益无法承受该负载，请提高增益（scenario --print --payload）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>trial %1 not learned from: %2</source>
        <translation>未从试验 %1 学习：%2</translation>
    </message>
</context>
<context>
    <name>PayloadText</name>
    <message>
        <location filename="../ui/PayloadText.cpp" line="+26"/>
        <source>seen</source>
        <translation>可见</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>not seen: kept at the prior</source>
        <translation>不可见：保持先验值</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1; the payload on &lt;b&gt;%2&lt;/b&gt;, the arm&apos;s model held fixed.</source>
        <translation>%1；负载位于 &lt;b&gt;%2&lt;/b&gt;，手臂模型保持不变。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The simulation carries %1 kg at %2 mm.</source>
        <translation>仿真携带 %1 kg，位于 %2 mm。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 baseline trial(s) of the same timed path without the payload, then %2 payload trial(s).</source>
        <translation>先在同一定时路径上不带负载进行 %1 次基线试验，然后进行 %2 次负载试验。</translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>%n payload trial(s), no baseline trial.</source>
        <translation>
            <numerusform>%n 次负载试验，无基线试验。</numerusform>
        </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The path determines &lt;b&gt;%1 of the payload&apos;s 10 parameters&lt;/b&gt;: mass %2, centre of mass %3, inertia %4.</source>
        <translation>该路径确定&lt;b&gt;负载 10 个参数中的 %1 个&lt;/b&gt;：质量%2，质心%3，惯量%4。</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>The first trial passes its check.</source>
        <translation>第一次试验通过检查。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The first trial would be refused: %1</source>
        <translation>第一次试验将被拒绝：%1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>The payload after trial %1: %2 of 10 directions determined (condition %3); bound: %4.</source>
        <translation>试验 %1 后的负载：10 个方向中确定了 %2 个（条件数 %3）；边界：%4。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Mass &lt;b&gt;%1 kg&lt;/b&gt; (standard error %2 kg), centre of mass &lt;b&gt;%3 mm&lt;/b&gt;.</source>
        <translation>质量 &lt;b&gt;%1 kg&lt;/b&gt;（标准误差 %2 kg），质心 &lt;b&gt;%3 mm&lt;/b&gt;。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Its centre of mass lies outside the bound.</source>
        <translation>其质心位于边界之外。</translation>
    </message>
</context>
<context>
    <name>Pdo</name>
    <message>
        <location filename="../core/can/Pdo.cpp" line="+24"/>
        <source>PDO %1 does not exist; learnid uses PDO 1 to 4.</source>
        <translation>PDO %1 不存在；learnid 使用 PDO 1 到 4。</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Object %1 of type %2 cannot be mapped into a PDO.</source>
        <translation>类型为 %2 的对象 %1 无法映射到 PDO。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The mapped objects need %1 bits; a PDO holds at most %2 bits (8 bytes).</source>
        <translation>映射的对象需要 %1 位；一个 PDO 最多容纳 %2 位（8 字节）。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>The PDO maps %1 objects but %2 values were given.</source>
        <translation>该 PDO 映射了 %1 个对象，但给出了 %2 个值。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>PDO object %1: %2</source>
        <translation>PDO 对象 %1：%2</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>The PDO carries %1 bytes; its mapping needs %2.</source>
        <translation>该 PDO 携带 %1 个字节；其映射需要 %2 个。</translation>
    </message>
</context>
<context>
    <name>PlanCsv</name>
    <message>
        <location filename="../core/io/PlanCsv.cpp" line="+109"/>
        <source>a second &quot;# %1:&quot; line; the first is on line %2</source>
        <translation>第二个“# %1:”行；第一个在第 %2 行</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>no &quot;# %1:&quot; line before the header</source>
        <translation>表头之前没有“# %1:”行</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+199"/>
        <source>the plan-id must be 64 hex digits (SHA-256), got %1</source>
        <translation>plan-id 必须是 64 位十六进制数字（SHA-256），实际为 %1</translation>
    </message>
    <message>
        <location line="-191"/>
        <source>expected &quot;# robot: &lt;model&gt;, &lt;n&gt; joints&quot;, got %1</source>
        <translation>应为“# robot: &lt;model&gt;, &lt;n&gt; joints”，实际为 %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the sample period must be a positive number [s], got %1</source>
        <translation>采样周期必须是正数 [s]，实际为 %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>estimate value %1 is not a finite number: %2</source>
        <translation>估计值 %1 不是有限数：%2</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>plan CSV: the plan (%1 joints, %2 samples, %3 feedforward columns) is empty, does not fit its feedforward or holds non-finite numbers</source>
        <translation>计划 CSV：计划（%1 个关节，%2 个采样点，%3 个前馈列）为空、与其前馈不符或含有非有限数</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>plan CSV: the estimate the feedforward was built with is empty or not finite</source>
        <translation>计划 CSV：用于构建前馈的估计为空或不是有限值</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>not a plan file of this version: the first line must be &quot;%1&quot;</source>
        <translation>不是此版本的计划文件：第一行必须是“%1”</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>no header line; expected %1</source>
        <translation>没有表头行；应为 %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the header of a plan of %1 joints is %2</source>
        <translation>%1 个关节的计划的表头为 %2</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>no samples after the header</source>
        <translation>表头之后没有采样点</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>a blank or comment line among the samples; comments go before the header</source>
        <translation>采样点之间有空行或注释行；注释应位于表头之前</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>expected %1 fields, got %2</source>
        <translation>应有 %1 个字段，实际为 %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>not a finite number: %1</source>
        <translation>不是有限数：%1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>sample %1 is at k Ts = %2 s, got %3 s</source>
        <translation>采样点 %1 应位于 k Ts = %2 s，实际为 %3 s</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>the plan-id %1 is not that of the plan&apos;s numbers (%2): the plan was changed after learnid wrote it</source>
        <translation>plan-id %1 与计划数值对应的 plan-id（%2）不符：计划在 learnid 写入后被修改过</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>a second plan-id, %1, other than %2 on line %3; a log is of one plan</source>
        <translation>第二个 plan-id %1 与第 %3 行的 %2 不同；一个日志只属于一个计划</translation>
    </message>
</context>
<context>
    <name>Plausibility</name>
    <message>
        <location filename="../core/model/Plausibility.cpp" line="+45"/>
        <source>The CAD vector has %1 entries, too few for %2 links.</source>
        <translation>CAD 向量有 %1 个元素，不足以描述 %2 个连杆。</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>The plausibility check needs 10 parameters and a volume per link (%1 links, %2 and %3 parameters, %4 volumes).</source>
        <translation>合理性检查需要每个连杆 10 个参数和一个包围体（%1 个连杆，%2 和 %3 个参数，%4 个包围体）。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The parameters to check are not finite.</source>
        <translation>待检查的参数不是有限值。</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>its mass is %1 kg: not a real body</source>
        <translation>其质量为 %1 kg：不是真实刚体</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>its smallest principal moment of inertia about the centre of mass, %1 kg m^2, is below %2 % of the CAD link&apos;s smallest (%3 kg m^2): a point mass or a needle, not a link</source>
        <translation>其绕质心的最小主惯性矩 %1 kg m^2 低于 CAD 连杆最小主惯性矩（%3 kg m^2）的 %2 %：是质点或细针，不是连杆</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>its principal moments %1, %2 and %3 kg m^2 give I1 + I2 = %4 I3, below %5 I3 (a flat plate at best)</source>
        <translation>其主惯性矩 %1、%2 和 %3 kg m^2 给出 I1 + I2 = %4 I3，低于 %5 I3（至多是一块薄板）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>its centre of mass lies outside its bounding volume (%1)</source>
        <translation>其质心位于包围体之外（%1）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the URDF&apos;s geometry: %1</source>
        <translation>URDF 的几何体：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the CAD body&apos;s inertia ellipsoid, enlarged %1 times</source>
        <translation>CAD 刚体的惯性椭球，放大 %1 倍</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>its centre of mass lies outside its bounding volume</source>
        <translation>其质心位于包围体之外</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Index %1 is outside the %2 standard parameters.</source>
        <translation>索引 %1 超出了 %2 个标准参数的范围。</translation>
    </message>
</context>
<context>
    <name>PlausibleEstimate</name>
    <message>
        <location filename="../core/model/PlausibleEstimate.cpp" line="+30"/>
        <source>The estimation problem&apos;s sizes do not match: A is %1 x %2, b has %3 entries, the prior %4 for %5 links.</source>
        <translation>估计问题的维度不匹配：A 为 %1 x %2，b 有 %3 个元素，先验有 %4 个，连杆 %5 个。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The estimation problem has entries that are not finite.</source>
        <translation>估计问题中有非有限的元素。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The prior share must lie between 0 and 1, not %1.</source>
        <translation>先验权重必须在 0 和 1 之间，而不是 %1。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 bounding volumes for %2 links.</source>
        <translation>%1 个包围体对应 %2 个连杆。</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+3"/>
        <source>Index %1 is not a joint term.</source>
        <translation>索引 %1 不是关节项。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The prior&apos;s joint term %1 is negative (%2).</source>
        <translation>先验的关节项 %1 为负（%2）。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The prior&apos;s link %1 does not lie inside its bounding volume.</source>
        <translation>先验的连杆 %1 不在其包围体内。</translation>
    </message>
    <message>
        <location line="+71"/>
        <source>The prior&apos;s link %1 is not strictly a real body (its pseudo-inertia is not positive definite).</source>
        <translation>先验的连杆 %1 不是严格意义上的真实刚体（其伪惯量不是正定的）。</translation>
    </message>
    <message numerus="yes">
        <location line="+61"/>
        <source>%n Newton step(s)</source>
        <translation>
            <numerusform>%n 个牛顿步</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>RecordedTrialRobot</name>
    <message>
        <location filename="../core/service/RecordedTrialRobot.cpp" line="+24"/>
        <source>the robot&apos;s own controller (plan and log files)</source>
        <translation>机器人自身的控制器（计划和日志文件）</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>no logged trial is left for trial run %1</source>
        <translation>试验运行 %1 已没有剩余的记录试验</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 ran plan %2, but with this scenario the trial is planned as %3: the scenario is not the one the plan was made with</source>
        <translation>%1 运行的是计划 %2，但在此场景下该试验被规划为 %3：此场景不是制定该计划时所用的场景</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>the robot&apos;s own controller takes its parameters its own way: give it the estimate&apos;s parameter file</source>
        <translation>机器人自身的控制器以自己的方式获取参数：请把该估计的参数文件交给它</translation>
    </message>
</context>
<context>
    <name>Robot</name>
    <message>
        <location filename="../core/robot/Robot.h" line="+39"/>
        <source>this robot&apos;s controller takes no payload: give it the payload&apos;s parameter file</source>
        <translation>该机器人的控制器不接收负载：请将负载的参数文件交给它</translation>
    </message>
</context>
<context>
    <name>RobotLogCsv</name>
    <message>
        <location filename="../core/io/RobotLogCsv.cpp" line="+49"/>
        <source>, ... (%1 columns)</source>
        <translation>, ...（共 %1 列）</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>the name repeats that of column %1; each column name may appear only once</source>
        <translation>该名称与第 %1 列的名称重复；每个列名只能出现一次</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>no column &quot;%1&quot; (%2); the header has: %3</source>
        <translation>没有列“%1”（%2）；表头包含：%3</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>the log has %1 joints (%2..%3), the robot %4</source>
        <translation>日志有 %1 个关节（%2..%3），机器人有 %4 个</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>the time [s]</source>
        <translation>时间 [s]</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the position of joint %1</source>
        <translation>关节 %1 的位置</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the velocity of joint %1, as the log has velocities of other joints</source>
        <translation>关节 %1 的速度，因为日志中有其他关节的速度</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the torque of joint %1</source>
        <translation>关节 %1 的力矩</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1: t= names no column; the time column is needed</source>
        <translation>%1：t= 未指定任何列；需要时间列</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1: %2=%3 has no %4 where the joint number goes, e.g. %2=%3%4</source>
        <translation>%1：%2=%3 中没有代表关节编号的 %4，例如 %2=%3%4</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1: &quot;%2&quot; has no &apos;=&apos;; expected key=pattern with the keys t, q, dq and tau, e.g. q=pos_meas%3</source>
        <translation>%1：“%2”中没有 &apos;=&apos;；应为“键=模式”的形式，键为 t、q、dq 和 tau，例如 q=pos_meas%3</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1: unknown key &quot;%2&quot;; the keys are t, q, dq and tau</source>
        <translation>%1：未知的键“%2”；键为 t、q、dq 和 tau</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: the key %2 is given twice</source>
        <translation>%1：键 %2 被给出两次</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1: a log is read for 1 joint or more, not %2</source>
        <translation>%1：日志只能按 1 个或更多关节读取，而不是 %2 个</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: %2 joint kinds given for a robot of %3 joints</source>
        <translation>%1：为有 %3 个关节的机器人给出了 %2 个关节类型</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>expected %1 fields (%2), got %3</source>
        <translation>应有 %1 个字段（%2），实际为 %3</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>the field is empty; expected a number</source>
        <translation>字段为空；应为数字</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not a number: %1</source>
        <translation>不是数字：%1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 rad/s is faster than any robot joint turns (at most %2 rad/s); the log looks like it holds degrees per second, radians per second are expected</source>
        <translation>%1 rad/s 超过了任何机器人关节的转速（最多 %2 rad/s）；日志中似乎是度每秒，而应为弧度每秒</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 rad is more than 1.05 turns (%2 rad); the log looks like it holds degrees, radians are expected</source>
        <translation>%1 rad 超过 1.05 圈（%2 rad）；日志中似乎是角度（度），而应为弧度</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>the times must increase from sample to sample, got %1 after %2 on line %3</source>
        <translation>时间必须逐个采样点递增，实际在第 %3 行的 %2 之后为 %1</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>the time %1 repeats that of line %2 with other values (%3: %4 there, %5 here); only an exact repeat of a row is dropped</source>
        <translation>时间 %1 与第 %2 行的相同，但数值不同（%3：那里为 %4，这里为 %5）；只有完全重复的行才会被丢弃</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>the file holds no header line; expected one naming the columns %1</source>
        <translation>文件中没有表头行；应有一行表头列出各列 %1</translation>
    </message>
    <message numerus="yes">
        <location line="+9"/>
        <source> (and %n stale row(s): values repeated under a new time stamp, treated as missing)</source>
        <translation>
            <numerusform>（另有 %n 行过时数据：在新时间戳下重复了之前的值，按缺失处理）</numerusform>
        </translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 samples after the header on line %2%3; a log needs at least %4</source>
        <translation>第 %2 行的表头之后有 %1 个采样点%3；日志至少需要 %4 个</translation>
    </message>
</context>
<context>
    <name>RobotScenario</name>
    <message>
        <location filename="../core/session/RobotScenario.cpp" line="+99"/>
        <source>controller.samplePeriod: the starter&apos;s gains do not hold the arm in discrete time at %1 ms, even with the derivative gains lowered (a pole at |z| = %2)</source>
        <translation>controller.samplePeriod：即使降低微分增益，起始场景的增益在 %1 ms 下也无法在离散时间内稳住机械臂（极点 |z| = %2）</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 deg</source>
        <translation>%1 deg</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>robot.model: unknown model &quot;%1&quot;</source>
        <translation>robot.model：未知模型“%1”</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>payload: only a URDF robot carries a payload</source>
        <translation>payload：只有 URDF 机器人才能携带负载</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>controller.samplePeriod: the paper scenario is the paper&apos;s, at %1 ms; pick a URDF robot for another clock</source>
        <translation>controller.samplePeriod：论文场景即论文中的场景，采样周期为 %1 ms；如需其他周期，请选择 URDF 机器人</translation>
    </message>
    <message>
        <location line="+159"/>
        <source>unknown robot &quot;%1&quot;; known: %2, or a URDF file (FILE.urdf)</source>
        <translation>未知机器人“%1”；已知：%2，或一个 URDF 文件（FILE.urdf）</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>path.waypoints[%1][%2]: %3 is %4 joint %5 (%6)&apos;s %7 limit %8</source>
        <translation>path.waypoints[%1][%2]：%3 %4关节 %5（%6）的%7 %8</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>below</source>
        <translation>低于</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>above</source>
        <translation>高于</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>lower</source>
        <translation>下限</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>upper</source>
        <translation>上限</translation>
    </message>
</context>
<context>
    <name>SafetyCheck</name>
    <message>
        <location filename="../core/session/SafetyCheck.cpp" line="+154"/>
        <source>joint %1 would reach %2 at t = %3 s, outside its limits %4 to %5</source>
        <translation>关节 %1 将在 t = %3 s 时到达 %2，超出其限位 %4 至 %5</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>joint %1 would move at %2 at t = %3 s, above its speed limit %4</source>
        <translation>关节 %1 将在 t = %3 s 时以 %2 运动，超过其速度上限 %4</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>the estimate is not a physical robot: its mass matrix is not positive definite at t = %1 s</source>
        <translation>该估计不是物理上可能的机器人：其质量矩阵在 t = %1 s 时不是正定的</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the closed loop would be unstable: linearised along the path with the current estimate, a pole has |z| = %1 (growth rate %2 1/s) at t = %3 s. Raise the derivative filter bandwidth lambda or lower the gains</source>
        <translation>闭环将不稳定：用当前估计沿路径线性化后，在 t = %3 s 时有一个极点 |z| = %1（增长率 %2 1/s）。请提高微分滤波器带宽 lambda 或降低增益</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>planned torque of joint %1 is %2 N m, above its limit of %3 N m</source>
        <translation>关节 %1 的计划力矩为 %2 N m，超过其限值 %3 N m</translation>
    </message>
</context>
<context>
    <name>ScenarioFile</name>
    <message>
        <location filename="../core/io/ScenarioValidation.cpp" line="+234"/>
        <source>must be %1, got %2</source>
        <translation>必须是%1，实际为 %2</translation>
    </message>
    <message>
        <location filename="../core/io/ScenarioFile.cpp" line="+299"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../core/io/ScenarioValidation.cpp" line="-157"/>
        <source>unknown model &quot;%1&quot;; known models: %2</source>
        <translation>未知模型“%1”；已知模型：%2</translation>
    </message>
    <message>
        <location line="+24"/>
        <location line="+60"/>
        <source>one per joint of %1</source>
        <translation>%1 的每个关节一个</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>unknown learning law &quot;%1&quot;; known laws: %2</source>
        <translation>未知学习律“%1”；已知学习律：%2</translation>
    </message>
    <message>
        <location line="-28"/>
        <source>one per parameter of %1</source>
        <translation>%1 的每个参数一个</translation>
    </message>
    <message>
        <location filename="../core/io/ScenarioFile.cpp" line="-265"/>
        <source>1 or -1</source>
        <translation>1 或 -1</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>must have 2 entries (x and y), got %1</source>
        <translation>必须有 2 个条目（x 和 y），实际为 %1</translation>
    </message>
    <message>
        <location line="+90"/>
        <source>this version of learnid reads &quot;%1&quot; and &quot;%2&quot;, got %3</source>
        <translation>此版本的 learnid 读取“%1”和“%2”，实际为 %3</translation>
    </message>
    <message>
        <location filename="../core/io/ScenarioValidation.cpp" line="-130"/>
        <source>one per joint</source>
        <translation>每个关节一个</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>the &quot;urdf&quot; model needs a URDF file</source>
        <translation>“urdf”模型需要 URDF 文件</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>the Cartesian line is the paper-2link arm&apos;s path; a URDF robot runs &quot;waypoints&quot; or &quot;file&quot;</source>
        <translation>笛卡尔直线是 paper-2link 机械臂的路径；URDF 机器人运行“waypoints”或“file”</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the paper-2link arm runs the Cartesian &quot;line&quot;</source>
        <translation>paper-2link 机械臂运行笛卡尔直线“line”</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>needs at least 2 waypoints, got %1</source>
        <translation>至少需要 2 个路点，实际为 %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>a path of kind &quot;file&quot; needs a CSV file</source>
        <translation>类型为“file”的路径需要 CSV 文件</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 has %2 joint columns, %3 has %4 joints</source>
        <translation>%1 有 %2 个关节列，%3 有 %4 个关节</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>must be 0 (off) or at least 1 (static friction is not below Coulomb friction), got %1</source>
        <translation>必须为 0（关闭）或至少为 1（静摩擦不低于库仑摩擦），实际为 %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>give static friction either as simulation.staticFriction or as this ratio, not both</source>
        <translation>静摩擦请用 simulation.staticFriction 或此比值之一给出，不可同时给出</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>applies to elastic joints only: give simulation.jointStiffness</source>
        <translation>仅适用于弹性关节：请给出 simulation.jointStiffness</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>must be 1 or -1, got %1</source>
        <translation>必须是 1 或 -1，实际为 %1</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>needs the improved law (estimator.law &quot;improved&quot;), got &quot;%1&quot;</source>
        <translation>需要改进律（estimator.law &quot;improved&quot;），实际为 &quot;%1&quot;</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>needs a URDF robot with robot.jointTerms.armature true: the rotor inertia the sensor does not see is learned as the armature term</source>
        <translation>需要 robot.jointTerms.armature 为 true 的 URDF 机器人：传感器看不到的转子惯量作为转子惯量项（armature）学习</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>must be 0 (an ideal encoder) or an integer from %1 to %2, got %3</source>
        <translation>必须是 0（理想编码器）或 %1 到 %2 之间的整数，实际为 %3</translation>
    </message>
    <message>
        <location filename="../core/io/ScenarioChain.cpp" line="+50"/>
        <source>must have 3 entries (x, y, z in the base link&apos;s frame), got %1</source>
        <translation>必须有 3 个条目（基座连杆坐标系中的 x、y、z），实际为 %1</translation>
    </message>
    <message>
        <location filename="../core/io/ScenarioPayload.cpp" line="+41"/>
        <source>x, y and z</source>
        <translation>x、y 和 z</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Ixx, Ixy, Iyy, Ixz, Iyz and Izz</source>
        <translation>Ixx、Ixy、Iyy、Ixz、Iyz 和 Izz</translation>
    </message>
    <message>
        <location line="+18"/>
        <location line="+78"/>
        <source>x0, y0, z0, x1, y1 and z1</source>
        <translation>x0、y0、z0、x1、y1 和 z1</translation>
    </message>
    <message>
        <location line="-74"/>
        <source>give the bound either as a sphere (radius) or as a box, not both</source>
        <translation>边界请给出球体（radius）或长方体（box）之一，不能同时给出</translation>
    </message>
    <message>
        <location line="+67"/>
        <source>only a URDF robot carries a payload (the model is %1)</source>
        <translation>只有 URDF 机器人才能携带负载（模型为 %1）</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>not a real body&apos;s inertia (principal moments %1, %2, %3 kg m^2 must not be negative and each at most the sum of the others)</source>
        <translation>不是真实物体的惯量（主惯量 %1、%2、%3 kg m^2 不得为负，且每个不得大于其余两个之和）</translation>
    </message>
</context>
<context>
    <name>ScenarioRobot</name>
    <message>
        <location filename="../core/session/ScenarioRobot.cpp" line="+73"/>
        <source>robot.torqueLimits: joint %1 (%2) has no effort limit in the URDF: give the torque limits in the scenario</source>
        <translation>robot.torqueLimits：关节 %1（%2）在 URDF 中没有 effort 限值：请在场景中给出力矩限值</translation>
    </message>
    <message>
        <location filename="../core/session/ScenarioRobotJoints.cpp" line="+79"/>
        <source>must be at least the simulated robot&apos;s Coulomb friction of joint %1, %2 N m, got %3</source>
        <translation>必须至少等于仿真机器人关节 %1 的库仑摩擦 %2 N m，实际为 %3</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>an elastic joint needs its motor&apos;s rotor inertia: give simulation.armature or simulation.armatureFactor above 0 for joint %1</source>
        <translation>弹性关节需要其电机的转子惯量：请为关节 %1 给出大于 0 的 simulation.armature 或 simulation.armatureFactor</translation>
    </message>
</context>
<context>
    <name>SdoAbortCode</name>
    <message>
        <location filename="../core/can/SdoAbortCode.cpp" line="+17"/>
        <source>Toggle bit not alternated.</source>
        <translation>触发位未交替。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SDO protocol timed out.</source>
        <translation>SDO 协议超时。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Client/server command specifier not valid or unknown.</source>
        <translation>客户端/服务器命令说明符无效或未知。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Invalid block size (block mode only).</source>
        <translation>块大小无效（仅块模式）。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Invalid sequence number (block mode only).</source>
        <translation>序列号无效（仅块模式）。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CRC error (block mode only).</source>
        <translation>CRC 错误（仅块模式）。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Out of memory.</source>
        <translation>内存不足。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unsupported access to an object.</source>
        <translation>不支持的对象访问。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Attempt to read a write-only object.</source>
        <translation>试图读取只写对象。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Attempt to write a read-only object.</source>
        <translation>试图写入只读对象。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Object does not exist in the object dictionary.</source>
        <translation>对象字典中不存在该对象。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Object cannot be mapped to the PDO.</source>
        <translation>对象无法映射到 PDO。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The number and length of the objects to be mapped would exceed the PDO length.</source>
        <translation>待映射对象的数量和长度将超出 PDO 长度。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>General parameter incompatibility.</source>
        <translation>一般参数不兼容。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>General internal incompatibility in the device.</source>
        <translation>设备内部一般不兼容。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Access failed due to a hardware error.</source>
        <translation>因硬件错误访问失败。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Data type does not match: the length of the service parameter does not match.</source>
        <translation>数据类型不匹配：服务参数的长度不匹配。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Data type does not match: the length of the service parameter is too high.</source>
        <translation>数据类型不匹配：服务参数的长度过长。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Data type does not match: the length of the service parameter is too low.</source>
        <translation>数据类型不匹配：服务参数的长度过短。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Sub-index does not exist.</source>
        <translation>子索引不存在。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Invalid value for the parameter (download only).</source>
        <translation>参数值无效（仅下载）。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Value of the parameter written too high (download only).</source>
        <translation>写入的参数值过高（仅下载）。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Value of the parameter written too low (download only).</source>
        <translation>写入的参数值过低（仅下载）。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Maximum value is less than minimum value.</source>
        <translation>最大值小于最小值。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Resource not available: SDO connection.</source>
        <translation>资源不可用：SDO 连接。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>General error.</source>
        <translation>一般错误。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Data cannot be transferred or stored to the application.</source>
        <translation>数据无法传输或存储到应用。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Data cannot be transferred or stored to the application because of local control.</source>
        <translation>因本地控制，数据无法传输或存储到应用。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Data cannot be transferred or stored to the application because of the present device state.</source>
        <translation>因当前设备状态，数据无法传输或存储到应用。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Object dictionary dynamic generation failed or no object dictionary is present.</source>
        <translation>对象字典动态生成失败或不存在对象字典。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>No data available.</source>
        <translation>无可用数据。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Unknown abort code %1.</source>
        <translation>未知中止代码 %1。</translation>
    </message>
</context>
<context>
    <name>SdoWrite</name>
    <message>
        <location filename="../core/can/SdoWrite.cpp" line="+14"/>
        <source>%1 is not a valid CANopen node id (1 to 127).</source>
        <translation>%1 不是有效的 CANopen 节点 ID（1 到 127）。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Node %1, object %2: %3</source>
        <translation>节点 %1，对象 %2：%3</translation>
    </message>
</context>
<context>
    <name>SessionExport</name>
    <message>
        <location filename="../core/service/SessionExport.cpp" line="+110"/>
        <source>only URDF robots have a URDF to export</source>
        <translation>只有 URDF 机器人才有可导出的 URDF</translation>
    </message>
    <message>
        <location line="-29"/>
        <source>no consistent estimate near estimate %1: %2</source>
        <translation>估计 %1 附近没有一致的估计：%2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>only URDF robots have standard parameters to make consistent</source>
        <translation>只有 URDF 机器人有可使其一致的标准参数</translation>
    </message>
    <message>
        <location line="+73"/>
        <source>cannot create the folder %1</source>
        <translation>无法创建文件夹 %1</translation>
    </message>
</context>
<context>
    <name>SessionReport</name>
    <message>
        <location filename="../core/service/SessionReport.cpp" line="+131"/>
        <source>estimate %1 does not exist in this session</source>
        <translation>本会话中不存在估计 %1</translation>
    </message>
</context>
<context>
    <name>SimulatedRobot</name>
    <message>
        <location filename="../core/robot/SimulatedRobot.cpp" line="+57"/>
        <source>simulated %1</source>
        <translation>仿真 %1</translation>
    </message>
    <message>
        <location line="+96"/>
        <source>tracking error of joint %1 reached %2 deg at t = %3 s (limit %4 deg): quick stop</source>
        <translation>关节 %1 的跟踪误差在 t = %3 s 时达到 %2 度（限值 %4 度）：快速停止</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>drive of joint 1 reported a fault at t = %1 s (injected)</source>
        <translation>关节 1 的驱动器在 t = %1 s 时报告故障（注入）</translation>
    </message>
    <message>
        <location line="-121"/>
        <source>stopped by the operator at t = %1 s</source>
        <translation>操作员在 t = %1 s 时停止</translation>
    </message>
    <message>
        <location line="+148"/>
        <source>the simulated controller refused the parameter write (injected fault); its stored parameters are unchanged</source>
        <translation>仿真控制器拒绝写入参数（注入故障）；其已存储参数未改变</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>parameter set has %1 values, the model needs %2 finite values</source>
        <translation>参数组有 %1 个值，模型需要 %2 个有限值</translation>
    </message>
</context>
<context>
    <name>StandardExport</name>
    <message>
        <location filename="../core/service/StandardExport.cpp" line="+38"/>
        <source>data</source>
        <translation>数据</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>undetermined (kept near the prior)</source>
        <translation>未确定（保持在先验附近）</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1 standard parameters given, the model has %2</source>
        <translation>给出了 %1 个标准参数，模型有 %2 个</translation>
    </message>
</context>
<context>
    <name>Text</name>
    <message>
        <location filename="../core/model/UrdfChain.cpp" line="+55"/>
        <source>%1: not a valid URDF: %2</source>
        <translation>%1：不是有效的 URDF：%2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the parser gave no reason</source>
        <translation>解析器未给出原因</translation>
    </message>
    <message>
        <location filename="../core/session/ScenarioRobot.cpp" line="-41"/>
        <source>simulation.realUrdf: %1 has %2 moving joints, the robot %3</source>
        <translation>simulation.realUrdf：%1 有 %2 个可动关节，机器人有 %3 个</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>simulation.realUrdf: joint %1 (%2) is placed differently from the robot&apos;s URDF: the real robot may differ in inertia and friction only</source>
        <translation>simulation.realUrdf：关节 %1（%2）的位置与机器人 URDF 中的不同：真实机器人只能在惯量和摩擦上有所不同</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>simulation.realUrdf: %1 is not a robot that could be built: %2</source>
        <translation>simulation.realUrdf：%1 不是可以制造出来的机器人：%2</translation>
    </message>
    <message>
        <location filename="../core/identify/UniformLog.cpp" line="+145"/>
        <source>%1: the time stamps are off the nominal times t0 + k T (T = %2 ms) by %3 ms at %4 (t = %5 s) and by %6 ms at %7 (t = %8 s), more than half a step apart: the samples are not equidistant (one lost or added?), so the nominal times do not apply</source>
        <translation>%1：时间戳偏离名义时刻 t0 + k T（T = %2 ms），在%4（t = %5 s）处偏离 %3 ms，在%7（t = %8 s）处偏离 %6 ms，两者相差超过半个步长：采样点不等距（丢失或多出了一个？），因此名义时刻不适用</translation>
    </message>
    <message>
        <location filename="../core/service/FileLoop.cpp" line="-45"/>
        <source>%1: %2 holds %3 parameters of robot %4; the scenario&apos;s robot %5 has %6</source>
        <translation>%1：%2 包含机器人 %4 的 %3 个参数；场景的机器人 %5 有 %6 个</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1: %2: parameter %3 is &quot;%4&quot;, the robot&apos;s is &quot;%5&quot;</source>
        <translation>%1：%2：参数 %3 为“%4”，而机器人的为“%5”</translation>
    </message>
    <message>
        <location filename="../core/session/ScenarioRobotJoints.cpp" line="-50"/>
        <source>needs a URDF robot (the link&apos;s inertia about its axis); %1 has none: give simulation.armature in kg m^2</source>
        <translation>需要 URDF 机器人（连杆绕其轴的惯量）；%1 没有：请以 kg m^2 给出 simulation.armature</translation>
    </message>
    <message>
        <location filename="../core/service/FileLoopParts.cpp" line="-52"/>
        <source>%1 ran plan %2, which the history %3 has learned from already as trial %4: plan the next trial and run that</source>
        <translation>%1 运行的是计划 %2，历史 %3 已将其作为试验 %4 学习过：请规划下一次试验并运行它</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1 ran plan %2, which the history %3 does not know; its plans to run are: %4</source>
        <translation>%1 运行的是计划 %2，而历史 %3 中没有该计划；其待运行的计划为：%4</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>none (plan the next trial first)</source>
        <translation>无（请先规划下一次试验）</translation>
    </message>
</context>
<context>
    <name>TorqueRule</name>
    <message>
        <location filename="../core/motion/TorqueRule.cpp" line="+23"/>
        <source>torque rule needs 2 grid points</source>
        <translation>力矩规则需要 2 个网格点</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>torque rule: the path has %1 joints, the robot model %2</source>
        <translation>力矩规则：路径有 %1 个关节，机器人模型有 %2 个</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>torque rule needs one positive limit per joint and a positive fraction</source>
        <translation>力矩规则需要每个关节一个正的限值和一个正的比例</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>gravity alone needs %1 N m at joint %2 on this path, more than %3 % of its %4 N m limit: no duration can meet the torque rule</source>
        <translation>仅重力就需要在该路径上于关节 %2 施加 %1 N m，超过其 %4 N m 限值的 %3 %：任何时长都无法满足力矩规则</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>the path needs no torque: check its length and the parameters</source>
        <translation>该路径不需要力矩：请检查其长度和参数</translation>
    </message>
</context>
<context>
    <name>TrialCsv</name>
    <message>
        <location filename="../core/io/TrialCsv.cpp" line="+55"/>
        <source>trial CSV: the record (%1 joints, %2 samples) does not fit its plan (%3 joints, %4 samples)</source>
        <translation>试验 CSV：记录（%1 个关节，%2 个采样点）与其计划（%3 个关节，%4 个采样点）不符</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>the file is empty; expected the header line</source>
        <translation>文件为空；应有表头行</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>the header must be %1 (for one or more joints), got %2</source>
        <translation>表头必须是 %1（适用于一个或多个关节），实际为 %2</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>expected %1 fields, got %2</source>
        <translation>应有 %1 个字段，实际为 %2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 is not a number: &quot;%2&quot;</source>
        <translation>%1 不是数字：“%2”</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>t_s must be finite and increase from line to line, got %1</source>
        <translation>t_s 必须有限且逐行递增，实际为 %1</translation>
    </message>
</context>
<context>
    <name>TrialPlanner</name>
    <message>
        <location filename="../core/session/TrialPlanner.cpp" line="-79"/>
        <source>the path has %1 joints, the robot %2</source>
        <translation>路径有 %1 个关节，机器人有 %2 个</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>only planar 2-link arms have Cartesian line kinematics</source>
        <translation>只有平面二连杆机械臂具有笛卡尔直线运动学</translation>
    </message>
</context>
<context>
    <name>TrialResult</name>
    <message numerus="yes">
        <location filename="../core/session/TrialResult.cpp" line="+36"/>
        <source>%n set-point(s) reached the drives after their SYNC (statusword bit 12): the drives held the previous one, so this trial&apos;s motion is not quite the plan&apos;s and neither is what it teaches; close other programs on this computer</source>
        <translation>
            <numerusform>%n 个设定值在其 SYNC 之后才到达驱动器（状态字第 12 位）：驱动器保持了上一个设定值，因此本次试验的运动与计划不完全一致，从中学到的也是如此；请关闭这台计算机上的其他程序</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>TrialSeries</name>
    <message>
        <location filename="../core/session/TrialSeries.cpp" line="+70"/>
        <source>Run all stops: %1 trials in a row stopped at the tracking limit, and trial %2 was no progress over trial %3 (stopped at t = %4 s with %5 deg, against t = %6 s with %7 deg)</source>
        <translation>全部运行停止：连续 %1 次试验在跟踪误差限值处停止，且试验 %2 相比试验 %3 没有进展（在 t = %4 s 以 %5 度停止，对比 t = %6 s 以 %7 度）</translation>
    </message>
    <message>
        <location line="+82"/>
        <source>trial %1 tracked worse than trial %2 (max %3 deg against %4 deg)</source>
        <translation>试验 %1 的跟踪比试验 %2 差（最大 %3 度，对比 %4 度）</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1; Accept proposes estimate %2, which tracked best</source>
        <translation>%1；“接受”建议跟踪最好的估计 %2</translation>
    </message>
</context>
<context>
    <name>TrialStatus</name>
    <message>
        <location filename="../core/types/Trial.cpp" line="+11"/>
        <source>completed</source>
        <translation>已完成</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>aborted</source>
        <translation>已中止</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>robot fault</source>
        <translation>机器人故障</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>refused</source>
        <translation>已拒绝</translation>
    </message>
</context>
<context>
    <name>TwoLinkArm</name>
    <message>
        <location filename="../core/model/TwoLinkArm.cpp" line="+15"/>
        <source>inertia of the base axis</source>
        <translation>基座轴的惯量</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>coupling inertia of the two links</source>
        <translation>两连杆的耦合惯量</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>inertia of the second link</source>
        <translation>第二连杆的惯量</translation>
    </message>
</context>
<context>
    <name>TwoLinkKinematics</name>
    <message>
        <location filename="../core/motion/TwoLinkKinematics.cpp" line="+39"/>
        <source>point (%1, %2) m is out of reach or at a singularity of the arm (link lengths %3 m and %4 m)</source>
        <translation>点 (%1, %2) m 超出机械臂的工作范围或处于奇异位形（连杆长度 %3 m 和 %4 m）</translation>
    </message>
</context>
<context>
    <name>UniformLog</name>
    <message>
        <location filename="../core/identify/UniformLog.cpp" line="-99"/>
        <source>sample %1</source>
        <translation>采样点 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>line %1</source>
        <translation>第 %1 行</translation>
    </message>
    <message>
        <location line="+19"/>
        <source> (line %1 is stale: it repeated the values of line %2 under a new time stamp and counts as missing)</source>
        <translation>（第 %1 行是过时数据：它在新时间戳下重复了第 %2 行的值，按缺失计）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source> (lines %1 to %2 are stale: %3 rows that repeated the values of line %4 under new time stamps and count as missing)</source>
        <translation>（第 %1 至 %2 行是过时数据：%3 行在新时间戳下重复了第 %4 行的值，按缺失计）</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1: a log of %2 times, %3 x %4 positions, %5 x %6 velocities, %7 x %8 torques and %9 line numbers; expected n x N for all</source>
        <translation>%1：日志有 %2 个时间、%3 x %4 个位置、%5 x %6 个速度、%7 x %8 个力矩和 %9 个行号；全部应为 n x N</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1: %2 samples; resampling needs at least 2</source>
        <translation>%1：%2 个采样点；重采样至少需要 2 个</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1: a value is not a finite number</source>
        <translation>%1：有一个值不是有限数</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: the times must increase from sample to sample, got %2 after %3</source>
        <translation>%1：时间必须逐个采样点递增，实际在 %3 之后为 %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: the log spans %2 to %3 s, too long to resample</source>
        <translation>%1：日志跨度为 %2 到 %3 s，太长，无法重采样</translation>
    </message>
    <message>
        <location line="+74"/>
        <source>%1: the period (%2 s) and the largest gap (%3 s) must be zero (the default) or positive</source>
        <translation>%1：周期（%2 s）和最大间隔（%3 s）必须为零（默认）或正数</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: the fit&apos;s filter bandwidth rho (%2 rad/s) must be positive</source>
        <translation>%1：拟合滤波器的带宽 rho（%2 rad/s）必须为正</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>%1 ms allowed (--max-gap)</source>
        <translation>允许的 %1 ms（--max-gap）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 ms allowed (--max-gap; by default half the time constant 1/rho of the fit&apos;s filter, rho = %2 rad/s, and at least %3 of the log&apos;s steps)</source>
        <translation>允许的 %1 ms（--max-gap；默认为拟合滤波器时间常数 1/rho 的一半，rho = %2 rad/s，且至少为日志步长的 %3 倍）</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: a gap of %2 ms after the sample at t = %3 s%4, more than the %5</source>
        <translation>%1：t = %3 s 处的采样点之后有 %2 ms 的间隔%4，超过%5</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: a period of %2 ms over the log&apos;s %3 s gives %4 samples; expected 2 to %5 (100 per sample of the log)</source>
        <translation>%1：以 %2 ms 的周期覆盖日志的 %3 s 会得到 %4 个采样点；应为 2 到 %5 个（日志每个采样点至多 100 个）</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1: values this close to the largest double cannot be interpolated</source>
        <translation>%1：如此接近 double 最大值的数值无法插值</translation>
    </message>
</context>
<context>
    <name>UrdfChain</name>
    <message>
        <location filename="../core/model/UrdfChain.cpp" line="+21"/>
        <source>%1: link &quot;%2&quot; has a negative mass (%3 kg)</source>
        <translation>%1：连杆“%2”的质量为负（%3 kg）</translation>
    </message>
    <message>
        <location line="+51"/>
        <source>%1: the robot branches at link &quot;%2&quot; (children %3): name the tip link of the chain</source>
        <translation>%1：机器人在连杆“%2”处分叉（子连杆 %3）：请指定运动链的末端连杆</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>%1: joint &quot;%2&quot; has no axis (zero vector)</source>
        <translation>%1：关节“%2”没有轴（零向量）</translation>
    </message>
    <message>
        <location line="+32"/>
        <location line="+4"/>
        <source>%1: no link &quot;%2&quot;</source>
        <translation>%1：没有连杆“%2”</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: link &quot;%2&quot; is not below link &quot;%3&quot;</source>
        <translation>%1：连杆“%2”不在连杆“%3”之下</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1: joint &quot;%2&quot; mimics another joint: mimic joints are not supported</source>
        <translation>%1：关节“%2”模仿另一个关节（mimic）：不支持 mimic 关节</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>%1: joint &quot;%2&quot; is floating or planar: only revolute, continuous, prismatic and fixed joints form a serial arm</source>
        <translation>%1：关节“%2”为浮动（floating）或平面（planar）关节：只有旋转（revolute、continuous）、移动（prismatic）和固定（fixed）关节能构成串联机械臂</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1: no moving joint between link &quot;%2&quot; and link &quot;%3&quot;</source>
        <translation>%1：连杆“%2”和连杆“%3”之间没有可动关节</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1: cannot read the URDF: %2</source>
        <translation>%1：无法读取 URDF：%2</translation>
    </message>
</context>
<context>
    <name>UrdfExport</name>
    <message>
        <location filename="../core/io/UrdfExport.cpp" line="+122"/>
        <source>%1: link &quot;%2&quot;: the identified body has an entry that is not a finite number</source>
        <translation>%1：连杆“%2”：辨识出的刚体有一个条目不是有限数</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: link &quot;%2&quot;: the identified mass (%3 kg) is not positive</source>
        <translation>%1：连杆“%2”：辨识出的质量（%3 kg）不为正</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: link &quot;%2&quot;: the identified inertia is not that of a physical body (its pseudo-inertia has the negative eigenvalue %3)</source>
        <translation>%1：连杆“%2”：辨识出的惯量不可能属于物理刚体（其伪惯量有负特征值 %3）</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: joint &quot;%2&quot;: the friction must be finite and not negative, got viscous %3 and Coulomb %4</source>
        <translation>%1：关节“%2”：摩擦必须为有限值且非负，实际为粘性 %3、库仑 %4</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: joint &quot;%2&quot;: the armature must be finite and not negative and the offset finite, got armature %3 and offset %4</source>
        <translation>%1：关节“%2”：转子惯量必须为有限非负值，偏置必须为有限值，实际转子惯量为 %3，偏置为 %4</translation>
    </message>
    <message>
        <location line="+158"/>
        <source>%1: the identified URDF reads back with another body or friction at link &quot;%2&quot; than was written</source>
        <translation>%1：辨识出的 URDF 读回后，连杆“%2”处的刚体或摩擦与写入的不同</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1: bodies for %2 and friction for %3 joints given, the chain has %4 moving joints</source>
        <translation>%1：给出了 %2 个关节的刚体和 %3 个关节的摩擦，而运动链有 %4 个可动关节</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1: the chain&apos;s moving joints (%2) are not the URDF&apos;s from link &quot;%3&quot; to link &quot;%4&quot; (%5): the chain was not read from this URDF</source>
        <translation>%1：运动链的可动关节（%2）不是 URDF 中从连杆“%3”到连杆“%4”的可动关节（%5）：该运动链不是从此 URDF 读取的</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1: line %2, column %3: not XML: %4</source>
        <translation>%1：第 %2 行第 %3 列：不是 XML：%4</translation>
    </message>
    <message>
        <location filename="../core/io/UrdfPayload.cpp" line="+98"/>
        <source>%1: the payload on link &quot;%2&quot; is not a real body (mass %3 kg)</source>
        <translation>%1：连杆“%2”上的负载不是真实刚体（质量 %3 kg）</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: no closing &lt;/robot&gt; to add the payload before</source>
        <translation>%1：没有可在其前添加负载的结束标记 &lt;/robot&gt;</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1: the URDF with the payload reads back with another body at link &quot;%2&quot; than was written</source>
        <translation>%1：带负载的 URDF 读回后，连杆“%2”处的刚体与写入的不同</translation>
    </message>
</context>
<context>
    <name>UrdfExtension</name>
    <message>
        <location filename="../core/model/UrdfExtension.cpp" line="+20"/>
        <source>%1: line %2, column %3: &lt;%4&gt;: %5</source>
        <translation>%1：第 %2 行，第 %3 列：&lt;%4&gt;：%5</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>unknown attribute &quot;%1&quot; (the attributes are armature and offset)</source>
        <translation>未知属性“%1”（属性为 armature 和 offset）</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 must be a finite number, got &quot;%2&quot;</source>
        <translation>%1 必须是有限数，实际为“%2”</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>given twice in joint &quot;%1&quot;</source>
        <translation>在关节“%1”中出现两次</translation>
    </message>
</context>
<context>
    <name>UrdfGeometry</name>
    <message>
        <location filename="../core/model/UrdfGeometry.cpp" line="+85"/>
        <source>%1: link &quot;%2&quot;, &lt;%3&gt; %4: %5</source>
        <translation>%1：连杆“%2”，&lt;%3&gt; %4：%5</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the box&apos;s size is negative or not a number</source>
        <translation>长方体的尺寸为负或不是数字</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the cylinder&apos;s radius or length is negative or not a number</source>
        <translation>圆柱体的半径或长度为负或不是数字</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the sphere&apos;s radius is negative or not a number</source>
        <translation>球体的半径为负或不是数字</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>the mesh&apos;s scale is not a number</source>
        <translation>网格的缩放比例不是数字</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>mesh &quot;%1&quot; of link &quot;%2&quot; skipped: %3</source>
        <translation>连杆“%2”的网格“%1”已跳过：%3</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>1 box</source>
        <translation>1 个长方体</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 boxes</source>
        <translation>%1 个长方体</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>1 cylinder</source>
        <translation>1 个圆柱体</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 cylinders</source>
        <translation>%1 个圆柱体</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>1 sphere</source>
        <translation>1 个球体</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 spheres</source>
        <translation>%1 个球体</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>1 mesh</source>
        <translation>1 个网格</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 meshes</source>
        <translation>%1 个网格</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>visual shapes of %1 (no collision shape)</source>
        <translation>%1 的可视形状（无碰撞形状）</translation>
    </message>
</context>
<context>
    <name>UrdfJointTree</name>
    <message>
        <location filename="../core/model/UrdfJointTree.cpp" line="+69"/>
        <source>%1: line %2, column %3: not well-formed XML: %4</source>
        <translation>%1：第 %2 行，第 %3 列：不是格式正确的 XML：%4</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1: joint &quot;%2&quot; connects link &quot;%3&quot; to itself</source>
        <translation>%1：关节“%2”将连杆“%3”连接到其自身</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: link &quot;%2&quot; is the child of two joints, &quot;%3&quot; and &quot;%4&quot;: the joints of a URDF form a tree</source>
        <translation>%1：连杆“%2”是两个关节“%3”和“%4”的子连杆：URDF 的关节必须构成一棵树</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1: the joints form a loop through links %2: the joints of a URDF form a tree</source>
        <translation>%1：关节经由连杆 %2 构成了环路：URDF 的关节必须构成一棵树</translation>
    </message>
</context>
<context>
    <name>ValueChecks</name>
    <message>
        <location filename="../core/io/ValueChecks.cpp" line="+23"/>
        <source>must be a finite number, got %1</source>
        <translation>必须是有限数，实际为 %1</translation>
    </message>
    <message>
        <location line="+62"/>
        <source>must be %1, got %2</source>
        <translation>必须是%1，实际为 %2</translation>
    </message>
    <message>
        <location line="-46"/>
        <source>must be a positive number, got %1</source>
        <translation>必须是正数，实际为 %1</translation>
    </message>
    <message>
        <location line="-9"/>
        <source>the drives store it as REAL32, so it must be a finite number of at most %1 in magnitude, got %2</source>
        <translation>驱动器以 REAL32 存储该值，因此它必须是绝对值不超过 %1 的有限数，实际为 %2</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>must be zero or a positive number, got %1</source>
        <translation>必须是零或正数，实际为 %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>must be zero, a positive number or unbounded (null), got %1</source>
        <translation>必须是零、正数或无界（null），实际为 %1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>must be from %1 to %2</source>
        <translation>必须在 %1 到 %2 之间</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>must be greater than %1 and at most %2</source>
        <translation>必须大于 %1 且不超过 %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>must be greater than %1 and less than %2</source>
        <translation>必须大于 %1 且小于 %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1, got %2</source>
        <translation>%1，实际为 %2</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>must have %1 entries (%2), got %3</source>
        <translation>必须有 %1 个条目（%2），实际为 %3</translation>
    </message>
</context>
<context>
    <name>learnid-cli</name>
    <message>
        <location filename="../app/cli/IdentifyCommand.cpp" line="+44"/>
        <source>--robot: &apos;%1&apos; is neither a URDF file nor a built-in robot (%2)</source>
        <translation>--robot：&apos;%1&apos; 既不是 URDF 文件，也不是内置机器人（%2）</translation>
    </message>
    <message>
        <location line="+58"/>
        <source>robot %1: %2, %3 moving joints</source>
        <translation>机器人 %1：%2，%3 个可动关节</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>learnid-cli: reading %1</source>
        <translation>learnid-cli：正在读取 %1</translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>fitting %1 standard parameters to %n log(s)</source>
        <translation>
            <numerusform>正在用 %n 个日志拟合 %1 个标准参数</numerusform>
        </translation>
    </message>
    <message>
        <location line="+49"/>
        <source>identified by learnid-cli %1 identify on %2</source>
        <translation>由 learnid-cli %1 identify 于 %2 辨识</translation>
    </message>
    <message>
        <location line="-99"/>
        <source>%1: torque predicted and measured</source>
        <translation>%1：预测力矩与测量力矩</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>learnid: %1 identified from logs</source>
        <translation>learnid：根据日志辨识 %1</translation>
    </message>
    <message>
        <location line="+66"/>
        <location line="+37"/>
        <location filename="../app/cli/LoopCommands.cpp" line="+19"/>
        <location filename="../app/cli/PayloadCommand.cpp" line="+215"/>
        <location filename="../app/cli/PayloadRunCommand.cpp" line="+137"/>
        <location line="+13"/>
        <location filename="../app/cli/RunCommand.cpp" line="+106"/>
        <location line="+9"/>
        <location line="+6"/>
        <location line="+13"/>
        <location line="+14"/>
        <location line="+69"/>
        <location line="+62"/>
        <location filename="../app/cli/main.cpp" line="+54"/>
        <source>learnid-cli: error: %1</source>
        <translation>learnid-cli：错误：%1</translation>
    </message>
    <message>
        <location line="-4"/>
        <source>--plots: cannot create %1</source>
        <translation>--plots：无法创建 %1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>wrote %1</source>
        <translation>已写入 %1</translation>
    </message>
    <message>
        <location filename="../app/cli/CliOptions.cpp" line="+71"/>
        <source>Usage: learnid-cli %1 [options]

%2

%3</source>
        <translation>用法：learnid-cli %1 [选项]

%2

%3</translation>
    </message>
    <message>
        <location filename="../app/cli/RunCommandLine.cpp" line="+25"/>
        <source>--robot: must be &apos;sim&apos; or &apos;can&apos;, got &apos;%1&apos;</source>
        <translation>--robot：必须是 &apos;sim&apos; 或 &apos;can&apos;，实际为 &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+7"/>
        <source>--%1 needs --robot can</source>
        <translation>--%1 需要 --robot can</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>--robot can needs --can-plugin (e.g. socketcan, virtualcan)</source>
        <translation>--robot can 需要 --can-plugin（例如 socketcan、virtualcan）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>--robot can needs --can-interface (e.g. can0)</source>
        <translation>--robot can 需要 --can-interface（例如 can0）</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>--can-drives: %1</source>
        <translation>--can-drives：%1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>--can-drives: %1 records no drives (robot.drives): export it from a session on CAN drives</source>
        <translation>--can-drives：%1 未记录驱动器 (robot.drives)：请从使用 CAN 驱动器的会话中导出</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>--nodes: %1 in &apos;%2&apos;</source>
        <translation>--nodes：&apos;%2&apos; 中 %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>--can-sync-timeout: must be a whole number of ms from 1 to 60000, got &apos;%1&apos;</source>
        <translation>--can-sync-timeout：必须是 1 到 60000 之间的整数毫秒，实际为 &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../app/cli/RunCommand.cpp" line="-207"/>
        <location filename="../app/cli/RunCommandLine.cpp" line="+9"/>
        <source>--nodes %1: %2</source>
        <translation>--nodes %1：%2</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../app/cli/RunCommandLine.cpp" line="+2"/>
        <source>--robot %1: %2</source>
        <translation>--robot %1：%2</translation>
    </message>
    <message>
        <location filename="../app/cli/CliOptions.cpp" line="+97"/>
        <source>Show this command&apos;s options.</source>
        <translation>显示此命令的选项。</translation>
    </message>
    <message>
        <location line="-73"/>
        <source>Print the default scenario.</source>
        <translation>输出默认场景。</translation>
    </message>
    <message>
        <location filename="../app/cli/LoopOptions.cpp" line="+44"/>
        <location filename="../app/cli/RunCommandLine.cpp" line="+14"/>
        <source>Scenario file (JSON, docs/scenario.md); default: the paper scenario.</source>
        <translation>场景文件（JSON，docs/scenario.md）；默认：论文场景。</translation>
    </message>
    <message>
        <location filename="../app/cli/RunCommandLine.cpp" line="+4"/>
        <source>Learning law: paper or improved.</source>
        <translation>学习律：paper 或 improved。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Learning trials, 1 to 100.</source>
        <translation>学习试验次数，1 到 100。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Write the session report (JSON) to FILE.</source>
        <translation>将会话报告（JSON）写入 FILE。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Write the parameter file (JSON and DCF) to FILE.</source>
        <translation>将参数文件（JSON 和 DCF）写入 FILE。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Write each trial&apos;s samples as CSV into DIR.</source>
        <translation>将每次试验的采样以 CSV 写入 DIR。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Accept and apply the final estimate to the robot.</source>
        <translation>接受最终估计并写入机器人。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Export and apply the nearest physically consistent estimate to the final one (URDF robots).</source>
        <translation>导出并应用与最终估计最接近的物理一致估计（URDF 机器人）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Folder that relative output paths are taken from; default: the current directory.</source>
        <translation>相对输出路径的基准文件夹；默认：当前目录。</translation>
    </message>
    <message>
        <location filename="../app/cli/IdentifyOptions.cpp" line="+229"/>
        <location filename="../app/cli/LoopOptions.cpp" line="+14"/>
        <location filename="../app/cli/RunCommandLine.cpp" line="+5"/>
        <source>No progress lines on stderr.</source>
        <translation>不在 stderr 上输出进度行。</translation>
    </message>
    <message>
        <location filename="../app/cli/RunCommandLine.cpp" line="+2"/>
        <source>sim (default) or can.</source>
        <translation>sim（默认）或 can。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>QCanBus plugin, e.g. socketcan or virtualcan.</source>
        <translation>QCanBus 插件，例如 socketcan 或 virtualcan。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CAN interface, e.g. can0.</source>
        <translation>CAN 接口，例如 can0。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>CANopen node id of each joint&apos;s drive, e.g. 1,2.</source>
        <translation>每个关节驱动器的 CANopen 节点号，例如 1,2。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Longest SYNC gap in a trial [ms].</source>
        <translation>试验中最长的 SYNC 间隔 [ms]。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Write each trial&apos;s CAN frames as a candump log into DIR.</source>
        <translation>将每次试验的 CAN 帧以 candump 日志写入 DIR。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>First commissioning: you confirmed that each node is the drive of its joint (docs/can-protocol.md 2.4).</source>
        <translation>首次调试：您已确认每个节点都是其关节的驱动器（docs/can-protocol.md 2.4）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>A parameter file of this robot: its drives&apos; identities (0x1018) must match.</source>
        <translation>本机器人的参数文件：其驱动器标识 (0x1018) 必须一致。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>A recorded trial (candump log); once per trial, in order.</source>
        <translation>一次记录的试验（candump 日志）；每次试验一个，按顺序。</translation>
    </message>
    <message>
        <location filename="../app/cli/CliOptions.cpp" line="-76"/>
        <source>Usage:
  learnid-cli scenario --print [--robot ROBOT]
      Print a complete scenario as JSON. ROBOT: paper (the default: the paper
      scenario), panda, puma560, double-pendulum or a URDF file; for a robot
      other than paper, the gains the window designs for it and a path of
      joint waypoints inside its limits. With --payload --payload-mass KG
      [--payload-com X,Y,Z] [--payload-link LINK] ...: a scenario that learns
      that payload, the gains designed for the arm carrying it. With
      --sample-period MS: gains that hold at the robot&apos;s clock (default 2 ms).
  learnid-cli run [--scenario FILE] [--estimator paper|improved] [--iterations N]
                  [--report FILE] [--export FILE] [--trial-csv DIR] [--apply]
                  [--consistent] [--workspace DIR] [--quiet]
      Run a commissioning session on the simulated robot. The table goes to
      stdout, progress to stderr. Relative output paths are taken from
      --workspace (default: the current directory). Files are written only
      when every trial completed.
      --robot can --can-plugin P --can-interface I [--nodes 1,2] [--can-log DIR]
      runs it on CiA 402 drives on a CAN bus instead (docs/can-protocol.md);
      --can-log writes every trial&apos;s frames as a candump log into DIR;
      --can-sync-timeout MS stops a trial when no SYNC comes for MS (default 20).
  learnid-cli replay --candump FILE [--candump FILE2 ...] [--scenario FILE]
                     [--estimator paper|improved] [--nodes 1,2] [--report FILE]
                     [--export FILE] [--trial-csv DIR] [--workspace DIR] [--quiet]
      Re-identify from recorded trials: the session runs again with each log
      (one per trial, in order) answering in place of the robot.
  learnid-cli identify --robot ROBOT --log FILE [--log FILE2 ...]
                       [--validate FILE ...] [--columns SPEC] [--joint-terms LIST]
                       [--rho R] [--prior-share S] [--velocity auto|measured|q]
                       [--max-gap MS] [--torque-sensor-lag MS] [--base-link L]
                       [--tip-link L] [--export FILE] [--urdf-out FILE] [--report FILE]
                       [--plots DIR] [--scenario FILE] [--workspace DIR] [--quiet]
      Identify a real robot&apos;s inertia and friction from its recorded logs (CSV)
      and compare the result with its URDF on the --validate logs.
  learnid-cli plan --out DIR [--scenario FILE] [--estimate FILE] [--history DIR]
                   [--workspace DIR] [--quiet]
      Plan the next trial for the robot&apos;s own controller: q_d(t) and tau_f(t)
      (DIR/plan.csv) and the pre-trial check (DIR/check.txt).
  learnid-cli learn --trial-log FILE [--scenario FILE] [--history DIR]
                    [--workspace DIR] [--quiet]
      Learn from the controller&apos;s log of a plan; the next plan uses the new
      estimate.
  learnid-cli COMMAND --help
      The options of one command.
</source>
        <translation>用法：
  learnid-cli scenario --print [--robot ROBOT]
      以 JSON 格式输出完整场景。ROBOT：paper（默认：论文场景）、panda、puma560、
      double-pendulum 或一个 URDF 文件；对于 paper 以外的机器人，给出窗口为其设计的
      增益，以及一条位于其关节限位内的关节路点路径。
      使用 --payload --payload-mass KG [--payload-com X,Y,Z] [--payload-link LINK] ...：
      生成学习该负载的场景，增益按携带该负载的机械臂设计。
      使用 --sample-period MS：增益在机器人的控制周期下保持稳定（默认 2 ms）。
  learnid-cli run [--scenario FILE] [--estimator paper|improved] [--iterations N]
                  [--report FILE] [--export FILE] [--trial-csv DIR] [--apply]
                  [--consistent] [--workspace DIR] [--quiet]
      在仿真机器人上运行一次调试会话。表格输出到 stdout，
      进度输出到 stderr。相对输出路径以 --workspace 为基准
      （默认：当前目录）。只有当所有试验都完成时
      才写入文件。
      --robot can --can-plugin P --can-interface I [--nodes 1,2] [--can-log DIR]
      改为在 CAN 总线上的 CiA 402 驱动器上运行（docs/can-protocol.md）；
      --can-log 将每次试验的帧以 candump 日志写入 DIR；
      --can-sync-timeout MS：MS 内无 SYNC 即停止试验（默认 20）。
  learnid-cli replay --candump FILE [--candump FILE2 ...] [--scenario FILE]
                     [--estimator paper|improved] [--nodes 1,2] [--report FILE]
                     [--export FILE] [--trial-csv DIR] [--workspace DIR] [--quiet]
      根据记录的试验重新辨识：会话再次运行，由每个日志
      （每次试验一个，按顺序）代替机器人应答。
  learnid-cli identify --robot ROBOT --log FILE [--log FILE2 ...]
                       [--validate FILE ...] [--columns SPEC] [--joint-terms LIST]
                       [--rho R] [--prior-share S] [--velocity auto|measured|q]
                       [--max-gap MS] [--torque-sensor-lag MS] [--base-link L]
                       [--tip-link L] [--export FILE] [--urdf-out FILE] [--report FILE]
                       [--plots DIR] [--scenario FILE] [--workspace DIR] [--quiet]
      根据真实机器人记录的日志（CSV）辨识其惯量和摩擦，
      并在 --validate 日志上将结果与其 URDF 进行比较。
  learnid-cli plan --out DIR [--scenario FILE] [--estimate FILE] [--history DIR]
                   [--workspace DIR] [--quiet]
      为机器人自身的控制器规划下一次试验：q_d(t) 和 tau_f(t)
      （DIR/plan.csv）以及试验前检查（DIR/check.txt）。
  learnid-cli learn --trial-log FILE [--scenario FILE] [--history DIR]
                    [--workspace DIR] [--quiet]
      从控制器按某个计划记录的日志中学习；下一个计划使用
      新的估计。
  learnid-cli COMMAND --help
      某个命令的选项。
</translation>
    </message>
    <message>
        <location line="+79"/>
        <source>The robot: paper (default), panda, puma560, double-pendulum, or a URDF file.</source>
        <translation>机器人：paper（默认）、panda、puma560、double-pendulum 或一个 URDF 文件。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The robot&apos;s clock in ms (default 2): the gains are designed to hold in discrete time at it.</source>
        <translation>机器人的控制周期，单位 ms（默认 2）：增益按在该周期下离散时间稳定来设计。</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Print a complete scenario for a robot as JSON.</source>
        <translation>以 JSON 格式输出某个机器人的完整场景。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&apos;scenario&apos; needs --print</source>
        <translation>&apos;scenario&apos; 需要 --print</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>--sample-period: the robot&apos;s clock must be a number of ms above 0 and at most 100, not &apos;%1&apos;</source>
        <translation>--sample-period：机器人的控制周期必须是大于 0 且不超过 100 的毫秒数，而不是 &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>no command given</source>
        <translation>未给出命令</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown command &apos;%1&apos;</source>
        <translation>未知命令 &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../app/cli/RunCommandLine.cpp" line="+18"/>
        <source>Re-identify from recorded trials: the session runs again with each log
answering in place of the robot.</source>
        <translation>根据记录的试验重新辨识：会话再次运行，
由每个日志代替机器人应答。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Run a commissioning session on the simulated robot, or with --robot can
on CiA 402 drives on a CAN bus (docs/can-protocol.md).</source>
        <translation>在仿真机器人上运行调试会话，或使用 --robot can
在 CAN 总线上的 CiA 402 驱动器上运行（docs/can-protocol.md）。</translation>
    </message>
    <message>
        <location filename="../app/cli/CliOptions.cpp" line="+38"/>
        <source>unexpected argument &apos;%1&apos;</source>
        <translation>意外的参数 &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../app/cli/RunCommandLine.cpp" line="+17"/>
        <source>--iterations: must be a whole number from 1 to 100, got &apos;%1&apos;</source>
        <translation>--iterations：必须是 1 到 100 之间的整数，实际为 &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>&apos;replay&apos; needs at least one --candump FILE</source>
        <translation>&apos;replay&apos; 至少需要一个 --candump FILE</translation>
    </message>
    <message>
        <location filename="../app/cli/ResultTable.cpp" line="+39"/>
        <location line="+76"/>
        <source>trial</source>
        <translation>试验</translation>
    </message>
    <message>
        <location line="-75"/>
        <location line="+78"/>
        <source>change %</source>
        <translation>变化 %</translation>
    </message>
    <message>
        <location line="-76"/>
        <location line="+78"/>
        <source>max|e|%1 deg</source>
        <translation>最大|e|%1 度</translation>
    </message>
    <message>
        <location line="-77"/>
        <location line="+78"/>
        <source>T s</source>
        <translation>T s</translation>
    </message>
    <message>
        <location line="-77"/>
        <location line="+78"/>
        <source>cond</source>
        <translation>cond</translation>
    </message>
    <message>
        <location line="-77"/>
        <source>rank</source>
        <translation>秩</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>path torque err %</source>
        <translation>路径力矩误差 %</translation>
    </message>
    <message>
        <location line="+29"/>
        <location line="+73"/>
        <source>learned from a partial trial</source>
        <translation>从部分试验中学习</translation>
    </message>
    <message>
        <location line="-65"/>
        <source>unit</source>
        <translation>单位</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>truth</source>
        <translation>真值</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>est %1</source>
        <translation>估计 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>  parameter</source>
        <translation>  参数</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>vs truth %</source>
        <translation>相对真值 %</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>(rank %1: unobservable kept)</source>
        <translation>（秩 %1：保留不可观测参数）</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>trial %1: %2</source>
        <translation>试验 %1：%2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>trial %1: %2, T = %3 s, no samples recorded</source>
        <translation>试验 %1：%2，T = %3 s，未记录采样</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>trial %1: %2, T = %3 s, %4 samples, max tracking error %5 deg</source>
        <translation>试验 %1：%2，T = %3 s，%4 个采样点，最大跟踪误差 %5 度</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>; learned from its first %1 s (a partial trial)</source>
        <translation>；从其前 %1 s 学习（部分试验）</translation>
    </message>
    <message>
        <location filename="../app/cli/RunCommand.cpp" line="-33"/>
        <source>--estimator: unknown law &apos;%1&apos; (known: %2)</source>
        <translation>--estimator：未知学习律 &apos;%1&apos;（已知：%2）</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>--nodes %1: %2 node ids for a robot of %3 joints: one node per joint is needed</source>
        <translation>--nodes %1：%2 个节点 ID，而机器人有 %3 个关节：每个关节需要一个节点</translation>
    </message>
    <message>
        <location line="+60"/>
        <source>--iterations: %1 trials need %1 recorded trials, the logs hold %2</source>
        <translation>--iterations：%1 次试验需要 %1 次已记录的试验，日志中有 %2 次</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>learnid-cli: %1, law %2, %3 learning trials</source>
        <translation>learnid-cli：%1，学习律 %2，%3 次学习试验</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>learnid-cli: warning: the URDF as a real robot: %1</source>
        <translation>learnid-cli：警告：该 URDF 作为真实机器人：%1</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>learnid-cli: estimate %1 tracked best: it is the one accepted, applied and exported</source>
        <translation>learnid-cli：估计 %1 跟踪最好：接受、应用和导出的是它</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>learnid-cli: %1 not written: nothing was learned</source>
        <translation>learnid-cli：未写入 %1：没有学到任何内容</translation>
    </message>
    <message>
        <location filename="../app/cli/PayloadRunCommand.cpp" line="-18"/>
        <location filename="../app/cli/RunCommand.cpp" line="+28"/>
        <source>learnid-cli: wrote %1 (the session ended early)</source>
        <translation>learnid-cli：已写入 %1（会话提前结束）</translation>
    </message>
    <message>
        <location filename="../app/cli/IdentifyCommand.cpp" line="-94"/>
        <location line="+93"/>
        <location filename="../app/cli/PayloadRunCommand.cpp" line="+80"/>
        <location filename="../app/cli/ResultTable.cpp" line="+7"/>
        <location filename="../app/cli/RunCommand.cpp" line="-112"/>
        <source>learnid-cli: %1</source>
        <translation>learnid-cli: %1</translation>
    </message>
    <message>
        <location filename="../app/cli/RunCommand.cpp" line="+15"/>
        <source>estimate %1:</source>
        <translation>估计 %1：</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the nearest consistent estimate changes the torques on the path by %1 % (--consistent exports and applies it)</source>
        <translation>最接近的一致估计使路径上的力矩改变 %1 %（--consistent 导出并应用它）</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>no consistent estimate found: %1</source>
        <translation>未找到一致的估计：%1</translation>
    </message>
    <message>
        <location filename="../app/cli/LoopCommands.cpp" line="+47"/>
        <source>trial %1 refused by the pre-trial check: %2</source>
        <translation>试验 %1 未通过试验前检查：%2</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+44"/>
        <location filename="../app/cli/RunCommand.cpp" line="+66"/>
        <source>learnid-cli: no files written</source>
        <translation>learnid-cli：未写入文件</translation>
    </message>
    <message>
        <location line="-36"/>
        <source>plan-id: %1</source>
        <translation>plan-id: %1</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>learnid-cli: baseline trial %1 (plan %2) kept; the next trial is a baseline trial too, without the payload</source>
        <translation>learnid-cli：基线试验 %1（计划 %2）已保留；下一次试验也是基线试验，不安装负载</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>learnid-cli: baseline trial %1 (plan %2) kept; mount the payload before the next trial</source>
        <translation>learnid-cli：基线试验 %1（计划 %2）已保留；请在下一次试验前安装负载</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>learnid-cli: trial %1 (plan %2) learned; the next plan uses estimate %3</source>
        <translation>learnid-cli：已从试验 %1（计划 %2）学习；下一个计划使用估计 %3</translation>
    </message>
    <message>
        <location filename="../app/cli/RunCommand.cpp" line="-30"/>
        <source>learnid-cli: error: apply failed: %1</source>
        <translation>learnid-cli：错误：写入失败：%1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>learnid-cli: estimate %1 applied to the robot</source>
        <translation>learnid-cli：估计 %1 已写入机器人</translation>
    </message>
    <message>
        <location filename="../app/cli/LoopCommands.cpp" line="-101"/>
        <location filename="../app/cli/PayloadRunCommand.cpp" line="-81"/>
        <location filename="../app/cli/RunCommand.cpp" line="+42"/>
        <source>learnid-cli: wrote %1</source>
        <translation>learnid-cli：已写入 %1</translation>
    </message>
    <message>
        <location filename="../app/cli/IdentifyOptions.cpp" line="-184"/>
        <source>--joint-terms: unknown term &apos;%1&apos;; the terms are armature, viscous, coulomb and offset, or none</source>
        <translation>--joint-terms：未知项 &apos;%1&apos;；可用的项为 armature、viscous、coulomb 和 offset，或 none</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>--rho: must be a positive number [rad/s], got &apos;%1&apos;</source>
        <translation>--rho：必须是正数 [rad/s]，实际为 &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>--prior-share: must be a number between 0 and 1, got &apos;%1&apos;</source>
        <translation>--prior-share：必须是 0 到 1 之间的数，实际为 &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>--velocity: must be auto, measured or q, got &apos;%1&apos;</source>
        <translation>--velocity：必须是 auto、measured 或 q，实际为 &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>--max-gap: must be a positive number of ms, got &apos;%1&apos;</source>
        <translation>--max-gap：必须是正的毫秒数，实际为 &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>--torque-sensor-lag: must be a number of ms from 0 to 1000, got &apos;%1&apos;</source>
        <translation>--torque-sensor-lag：必须是 0 到 1000 之间的毫秒数，实际为 &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>--urdf-out: %1 is where --export writes</source>
        <translation>--urdf-out：%1 已是 --export 的写入位置</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>A built-in URDF robot (e.g. double-pendulum) or a URDF file.</source>
        <translation>内置 URDF 机器人（例如 double-pendulum）或 URDF 文件。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>A recorded log (CSV) to identify from; once per log.</source>
        <translation>用于辨识的记录日志（CSV）；每个日志一个。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>A recorded log to check the result on; once per log.</source>
        <translation>用于检验结果的记录日志；每个日志一个。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The log&apos;s column names, e.g. t=time,q=pos%1,dq=vel%1,tau=tau%1.</source>
        <translation>日志的列名，例如 t=time,q=pos%1,dq=vel%1,tau=tau%1。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Joint terms to identify: armature, viscous, coulomb, offset, or none; default: viscous,coulomb,offset.</source>
        <translation>要辨识的关节项：armature、viscous、coulomb、offset 或 none；默认：viscous,coulomb,offset。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Bandwidth of the zero-phase log filter [rad/s]; default 50.</source>
        <translation>零相位日志滤波器的带宽 [rad/s]；默认 50。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Directions weaker than this share of the strongest keep the URDF&apos;s values; default 0.03.</source>
        <translation>弱于最强方向的此比例的方向保持 URDF 的值；默认 0.03。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Joint velocities: auto, measured or q (from positions).</source>
        <translation>关节速度：auto、measured 或 q（由位置求得）。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Longest time step allowed in a log [ms]; default half the time constant 1/rho of the fit&apos;s filter (10 ms at rho 50), at least 2.5 sample periods.</source>
        <translation>日志中允许的最长时间步长 [ms]；默认为拟合滤波器时间常数 1/rho 的一半（rho 为 50 时为 10 ms），至少 2.5 个采样周期。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>First-order lag of the torque sensors [ms], undone on the log&apos;s grid before the fit; default 0 (as measured).</source>
        <translation>力矩传感器的一阶滞后 [ms]，在拟合前于日志的时间网格上消除；默认 0（按测量值）。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The chain&apos;s base link; default: the URDF&apos;s root.</source>
        <translation>运动链的基座连杆；默认：URDF 的根连杆。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The chain&apos;s tip link; default: the one leaf below the base.</source>
        <translation>运动链的末端连杆；默认：基座之下唯一的叶连杆。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Write the identified model as a parameter file (and DCF); it records controller gains only with --scenario.</source>
        <translation>将识别出的模型写为参数文件（及 DCF）；仅在给出 --scenario 时记录控制器增益。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Write the URDF with the identified inertia and friction.</source>
        <translation>写出带有辨识出的惯量和摩擦的 URDF。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Write the report (PDF): the tables and the torque plots.</source>
        <translation>写出报告（PDF）：表格和力矩图。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Write the predicted and measured torque of each validation log as PNG into this folder (made if missing).</source>
        <translation>将每个验证日志的预测力矩与测量力矩以 PNG 写入此文件夹（不存在时自动创建）。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Scenario whose controller gains the parameter file records.</source>
        <translation>场景，其控制器增益记录在参数文件中。</translation>
    </message>
    <message>
        <location line="+5"/>
        <location filename="../app/cli/LoopOptions.cpp" line="-2"/>
        <source>Folder that relative output paths are taken from.</source>
        <translation>相对输出路径的基准文件夹。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Usage: learnid-cli identify --robot ROBOT --log FILE [options]

Identify a robot&apos;s inertia and joint friction from its recorded logs,
and compare the result with the URDF as given on --validate logs.

%1</source>
        <translation>用法：learnid-cli identify --robot ROBOT --log FILE [选项]

根据机器人记录的日志辨识其惯量和关节摩擦，
并在 --validate 日志上将结果与给定的 URDF 进行比较。

%1</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>&apos;identify&apos; needs --robot ROBOT</source>
        <translation>&apos;identify&apos; 需要 --robot ROBOT</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&apos;identify&apos; needs at least one --log FILE</source>
        <translation>&apos;identify&apos; 至少需要一个 --log FILE</translation>
    </message>
    <message>
        <location filename="../app/cli/IdentifyTable.cpp" line="+25"/>
        <location line="+16"/>
        <source>name</source>
        <translation>名称</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>joint</source>
        <translation>关节</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Identified parameters: %1.</source>
        <translation>辨识出的参数：%1。</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>training logs: residual of the fit</source>
        <translation>训练日志：拟合残差</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>RMS residual [N m]</source>
        <translation>RMS 残差 [N m]</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>ratio %</source>
        <translation>比值 %</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RMS error [N m]</source>
        <translation>RMS 误差 [N m]</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>validation on %1 (%2 samples)</source>
        <translation>在 %1 上验证（%2 个采样点）</translation>
    </message>
    <message>
        <location line="+4"/>
        <location filename="../app/cli/TorquePlotPng.cpp" line="+154"/>
        <source>URDF as given</source>
        <translation>给定的 URDF</translation>
    </message>
    <message>
        <location filename="../app/cli/IdentifyParameters.cpp" line="+33"/>
        <source>standard parameters: the URDF&apos;s, the identified, and what the data determined (share of the parameter&apos;s direction; at least 0.5: the data&apos;s, below: undetermined, kept near the prior, which the data still move a little)</source>
        <translation>标准参数：URDF 的值、识别值以及数据确定的程度（参数方向的份额；至少 0.5：来自数据，低于此值：未确定，保持在先验附近，数据仍会使其略有变化）</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>link or joint</source>
        <translation>连杆或关节</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>parameter</source>
        <translation>参数</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>URDF</source>
        <translation>URDF</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../app/cli/IdentifyTable.cpp" line="+1"/>
        <location filename="../app/cli/TorquePlotPng.cpp" line="+2"/>
        <source>identified</source>
        <translation>辨识结果</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>determined</source>
        <translation>确定份额</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>source</source>
        <translation>来源</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>warning: the URDF as a real robot: %1</source>
        <translation>警告：将该 URDF 视为真实机器人：%1</translation>
    </message>
    <message>
        <location filename="../app/cli/IdentifyTable.cpp" line="+2"/>
        <source>RMS measured [N m]</source>
        <translation>RMS 测量值 [N m]</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>overall sqrt(sum e^2 / sum tau^2) %</source>
        <translation>总体 sqrt(sum e^2 / sum tau^2) %</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>mean of the joint ratios %</source>
        <translation>各关节比值的平均 %</translation>
    </message>
    <message>
        <location filename="../app/cli/LoopOptions.cpp" line="-37"/>
        <source>Usage: learnid-cli plan --out DIR [options]

Plan the next trial for the robot&apos;s own controller: q_d(t) and the
feedforward tau_f(t) per joint (DIR/plan.csv) and the pre-trial check
(DIR/check.txt). A plan that fails the check is not written.

%1</source>
        <translation>用法：learnid-cli plan --out DIR [选项]

为机器人自身的控制器规划下一次试验：每个关节的 q_d(t) 和
前馈 tau_f(t)（DIR/plan.csv）以及试验前检查
（DIR/check.txt）。未通过检查的计划不会被写出。

%1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Usage: learnid-cli learn --trial-log FILE [options]

Learn from the log the robot&apos;s own controller recorded while running a
plan: the new estimate joins the history, the convergence table goes to
stdout, and the next plan uses the new estimate.

%1</source>
        <translation>用法：learnid-cli learn --trial-log FILE [选项]

从机器人自身的控制器运行计划时记录的日志中学习：
新的估计加入历史，收敛表输出到 stdout，
下一个计划使用新的估计。

%1</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>The learning history&apos;s folder; default: learnid-history beside plan.csv (plan) or the trial log (learn).</source>
        <translation>学习历史的文件夹；默认：plan.csv 旁（plan）或试验日志旁（learn）的 learnid-history。</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Folder to write plan.csv and check.txt into.</source>
        <translation>写入 plan.csv 和 check.txt 的文件夹。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Parameter file of the estimate to plan with; default: the history&apos;s newest, or the scenario&apos;s initial estimate.</source>
        <translation>用于规划的估计的参数文件；默认：历史中最新的估计，或场景的初始估计。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The controller&apos;s log of a run of the plan (CSV); once per repetition.</source>
        <translation>控制器运行该计划一次所记录的日志（CSV）；每次重复一个。</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>&apos;plan&apos; needs --out DIR</source>
        <translation>&apos;plan&apos; 需要 --out DIR</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&apos;learn&apos; needs --trial-log FILE</source>
        <translation>&apos;learn&apos; 需要 --trial-log FILE</translation>
    </message>
    <message>
        <location filename="../app/cli/TorquePlotPng.cpp" line="-26"/>
        <source>joint %1 (%2) [N m]</source>
        <translation>关节 %1（%2）[N m]</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>measured</source>
        <translation>测量值</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>t [s]</source>
        <translation>t [s]</translation>
    </message>
    <message>
        <location filename="../app/cli/ScenarioCommand.cpp" line="+49"/>
        <source>learnid-cli: error: --robot %1: %2</source>
        <translation>learnid-cli：错误：--robot %1：%2</translation>
    </message>
    <message>
        <location filename="../app/cli/PayloadCommand.cpp" line="-168"/>
        <source>value</source>
        <translation>量</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>estimate</source>
        <translation>估计值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>std. error</source>
        <translation>标准误差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>prior</source>
        <translation>先验</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>from</source>
        <translation>来源</translation>
    </message>
    <message>
        <location line="+57"/>
        <source>the logs</source>
        <translation>日志</translation>
    </message>
    <message>
        <location line="-45"/>
        <source>the prior (not identified)</source>
        <translation>先验（未辨识）</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1 on %2</source>
        <translation>%1（基于 %2）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Payload on %1 of %2; the arm&apos;s model (%3) held fixed.
</source>
        <translation>%2 的 %1 上的负载；机械臂模型（%3）保持固定。
</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Warning: the arm&apos;s model is %1 as given (its CAD values), not one identified earlier: its errors go into the payload&apos;s estimate. Identify the arm first (identify --export or --urdf-out, without the payload) and give that file as --robot.</source>
        <translation>警告：机械臂模型是原样给出的 %1（其 CAD 值），而不是先前辨识的模型：其误差会进入负载估计。请先辨识机械臂（identify --export 或 --urdf-out，不带负载），再将该文件作为 --robot 给出。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Note: %1</source>
        <translation>注意：%1</translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>Fitted to %n log(s), %1 samples: %2 of 10 directions determined (condition %3).
</source>
        <translation>
            <numerusform>已拟合 %n 个日志，%1 个采样：10 个方向中确定了 %2 个（条件数 %3）。
</numerusform>
        </translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Baseline %1 taken out of %2: shifted by %3 s, joint angles %4 deg RMS apart.
</source>
        <translation>已从 %2 中减去基线 %1：平移 %3 s，关节角相差 %4 度 RMS。
</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Warning: the plausible estimate did not converge (%1).
</source>
        <translation>警告：合理估计未收敛（%1）。
</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>A real body whose mass lies in the bound (%1).
</source>
        <translation>一个质量位于边界内的真实物体（%1）。
</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Warning: the centre of mass lies outside the bound (%1).
</source>
        <translation>警告：质心位于边界之外（%1）。
</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>What the logs did not show (kept from the prior):
</source>
        <translation>日志未显示的部分（保留先验）：
</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Torque residual per joint on the logs [N m]:</source>
        <translation>各关节在日志上的力矩残差 [N m]：</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>learnid-cli: fitting the payload to %1</source>
        <translation>learnid-cli：正在将负载拟合到 %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>On the --validate logs: &quot;URDF as given&quot; is the arm without the payload, &quot;identified&quot; the arm with it.
</source>
        <translation>在 --validate 日志上：“给定的 URDF”是不带负载的机械臂，“已辨识”是带负载的机械臂。
</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1: torque of the arm alone and with the payload</source>
        <translation>%1：机械臂单独及带负载时的力矩</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>learnid: payload on %1 identified from logs</source>
        <translation>learnid：根据日志辨识的 %1 上的负载</translation>
    </message>
    <message>
        <location filename="../app/cli/PayloadOptions.cpp" line="+42"/>
        <source>Identify only a payload fixed to the arm, the --robot URDF or parameter file held fixed as the arm&apos;s model; needs --payload-mass.</source>
        <translation>仅辨识固定在机械臂上的负载，--robot 的 URDF 或参数文件作为机械臂模型保持不变；需要 --payload-mass。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The link the payload is fixed to; default: the tip link.</source>
        <translation>负载所固定的连杆；默认：末端连杆。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Your estimate of the payload&apos;s mass [kg].</source>
        <translation>您对负载质量的估计 [kg]。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Your estimate of its centre of mass in the link frame [m]; default 0,0,0 (the flange).</source>
        <translation>您对其在连杆坐标系中质心的估计 [m]；默认 0,0,0（法兰）。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Your estimate of its inertia about the centre of mass [kg m^2]; default: a uniform sphere.</source>
        <translation>您对其绕质心惯量的估计 [kg m^2]；默认：均匀球体。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The payload lies within this distance of the flange [m]; default 0.3.</source>
        <translation>负载位于距法兰此距离之内 [m]；默认 0.3。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Or within this box in the link frame [m], instead of the sphere.</source>
        <translation>或位于连杆坐标系中的此长方体内 [m]，代替球。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>With --payload and a --robot parameter file of a URDF robot: the URDF the arm was identified on.</source>
        <translation>与 --payload 及 URDF 机器人的 --robot 参数文件一起使用：辨识机械臂时所用的 URDF。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>With --payload: a log of the same motion without the payload, whose torque residual is taken out of every --log (may be repeated; docs/payload.md).</source>
        <translation>与 --payload 一起使用：同一运动不带负载的日志，其力矩残差将从每个 --log 中减去（可重复；docs/payload.md）。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>A scenario that learns a payload fixed to the arm, the gains designed for the arm carrying the prior; needs --payload-mass.</source>
        <translation>生成学习固定在机械臂上的负载的场景，增益按携带先验负载的机械臂设计；需要 --payload-mass。</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>--%1: needs --payload</source>
        <translation>--%1：需要 --payload</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>--payload: needs --payload-mass KG, your estimate of the payload&apos;s mass</source>
        <translation>--payload：需要 --payload-mass KG，即您对负载质量的估计</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>--payload-box: give either a bounding box or --payload-radius, not both</source>
        <translation>--payload-box：请给出包围长方体或 --payload-radius，不要同时给出</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>--payload-mass: must be a number of kg, got &apos;%1&apos;</source>
        <translation>--payload-mass：必须是千克数，收到“%1”</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>--payload-com: must be three numbers X,Y,Z [m], got &apos;%1&apos;</source>
        <translation>--payload-com：必须是三个数 X,Y,Z [m]，收到“%1”</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>--payload-inertia: must be six numbers IXX,IXY,IYY,IXZ,IYZ,IZZ [kg m^2], got &apos;%1&apos;</source>
        <translation>--payload-inertia：必须是六个数 IXX,IXY,IYY,IXZ,IYZ,IZZ [kg m^2]，收到“%1”</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>--payload-radius: must be a number of m, got &apos;%1&apos;</source>
        <translation>--payload-radius：必须是米数，收到“%1”</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>--payload-box: must be six numbers X0,Y0,Z0,X1,Y1,Z1 [m], got &apos;%1&apos;</source>
        <translation>--payload-box：必须是六个数 X0,Y0,Z0,X1,Y1,Z1 [m]，收到“%1”</translation>
    </message>
    <message>
        <location filename="../app/cli/PayloadTrialTable.cpp" line="+20"/>
        <source>all</source>
        <translation>全部</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>baseline: the same path without the payload</source>
        <translation>基线：不带负载的同一路径</translation>
    </message>
    <message>
        <location filename="../app/cli/PayloadRunCommand.cpp" line="-69"/>
        <source>learnid-cli: take the payload off %1 for the %2 baseline trial(s), then press Enter (Ctrl-C stops)</source>
        <translation>learnid-cli：请为 %2 次基准试验从 %1 上卸下负载，然后按回车键（Ctrl-C 停止）</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>learnid-cli: the baseline trials are done: mount the payload on %1, then press Enter (Ctrl-C stops)</source>
        <translation>learnid-cli：基准试验已完成：请将负载安装到 %1 上，然后按回车键（Ctrl-C 停止）</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>stopped (Ctrl-C) before trial %1</source>
        <translation>在试验 %1 之前已停止（Ctrl-C）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>before trial %1: no answer on standard input, so the payload&apos;s state was not confirmed</source>
        <translation>试验 %1 之前：标准输入上没有回答，因此负载的状态未被确认</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>cannot create the folder %1</source>
        <translation>无法创建文件夹 %1</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>--apply: the simulated robot carries its payload already; --apply writes the payload to the drives of --robot can</source>
        <translation>--apply：仿真机器人已带有其负载；--apply 将负载写入 --robot can 的驱动器</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1: not available with a payload section yet (the payload is learned on the simulated or the CAN robot; --export, --report and --trial-csv write its files)</source>
        <translation>%1：带有 payload 部分时尚不可用（负载在仿真机器人或 CAN 机器人上学习；--export、--report 和 --trial-csv 写出其文件）</translation>
    </message>
    <message>
        <location line="+98"/>
        <source>trial %1 ended the run</source>
        <translation>试验 %1 结束了运行</translation>
    </message>
    <message>
        <location line="-75"/>
        <source>learnid-cli: %1, the payload on %2 learned in %3 trials; the arm&apos;s model is held fixed (robot.initialParameters)</source>
        <translation>learnid-cli：%1，在 %3 次试验中学习 %2 上的负载；机械臂模型保持固定（robot.initialParameters）</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>learnid-cli: first %1 baseline trial(s) of the same timed path without the payload, taken out of every payload trial (payload.baselineTrials)</source>
        <translation>learnid-cli：先进行 %1 次不带负载、同一定时路径的基线试验，并从每次负载试验中减去（payload.baselineTrials）</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>learnid-cli: the path determines %1 of the payload&apos;s 10 parameters</source>
        <translation>learnid-cli：该路径可确定负载 10 个参数中的 %1 个</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>apply failed: %1</source>
        <translation>应用失败：%1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>learnid-cli: the payload applied to the robot (0x2500 on every node, stored)</source>
        <translation>learnid-cli：负载已应用到机器人（每个节点的 0x2500，已存储）</translation>
    </message>
    <message>
        <location line="-146"/>
        <source>learnid-cli: %1 not written: the session ended before its last trial</source>
        <translation>learnid-cli：未写入 %1：会话在最后一次试验之前结束</translation>
    </message>
    <message>
        <location filename="../app/cli/PayloadTrialTable.cpp" line="-22"/>
        <source>trial  max error  RMS error  mass [kg]  centre of mass [mm]    update  identified</source>
        <translation>试验   最大误差   RMS误差   质量[kg]   质心 [mm]              更新    已辨识</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>          [deg]      [deg]                                       [ms]</source>
        <translation>          [°]        [°]                                          [ms]</translation>
    </message>
    <message>
        <location line="+32"/>
        <source> (stopped at the limit: learned up to the stop)</source>
        <translation>（在限值处停止：已学习到停止时）</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>The payload after trial %1 (bound: %2):</source>
        <translation>试验 %1 之后的负载（边界：%2）：</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the trials</source>
        <translation>试验</translation>
    </message>
</context>
<context>
    <name>learnid-robot-sim</name>
    <message>
        <location filename="../app/robot-sim/StopRequests.cpp" line="+67"/>
        <source>SIGINT</source>
        <translation>SIGINT</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SIGTERM</source>
        <translation>SIGTERM</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>stdin closed</source>
        <translation>stdin 已关闭</translation>
    </message>
    <message>
        <location filename="../app/robot-sim/main.cpp" line="+34"/>
        <source>learnid-robot-sim: error: %1</source>
        <translation>learnid-robot-sim：错误：%1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Try &apos;learnid-robot-sim --help&apos; for the options.</source>
        <translation>选项请见 &apos;learnid-robot-sim --help&apos;。</translation>
    </message>
    <message>
        <location filename="../app/robot-sim/SimOptions.cpp" line="+22"/>
        <source>--nodes: &apos;%1&apos; is not a CANopen node id (1 to 127) in &apos;%2&apos;</source>
        <translation>--nodes：&apos;%2&apos; 中的 &apos;%1&apos; 不是 CANopen 节点 ID（1 到 127）</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>--nodes: node %1 is listed twice in &apos;%2&apos;</source>
        <translation>--nodes：节点 %1 在 &apos;%2&apos; 中被列出两次</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>--refuse-sdo: &apos;%1&apos; is not an object address INDEX:SUB such as 0x2200:1 (index in hex, sub-index 0 to 255)</source>
        <translation>--refuse-sdo：&apos;%1&apos; 不是形如 0x2200:1 的对象地址 INDEX:SUB（索引为十六进制，子索引 0 到 255）</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>--%1: &apos;%2&apos; is not a whole number of at least %3</source>
        <translation>--%1：&apos;%2&apos; 不是不小于 %3 的整数</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>The robot on a CAN bus: one simulated CiA 402 drive per joint, the SYNC producer and the scenario&apos;s simulated arm. Prints &quot;ready&quot; once connected; runs until SIGINT, SIGTERM or stdin closes.</source>
        <translation>CAN 总线上的机器人：每个关节一个仿真 CiA 402 驱动器、SYNC 生产者以及场景的仿真机械臂。连接后输出“ready”；运行直到收到 SIGINT、SIGTERM 或 stdin 关闭。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Show this help.</source>
        <translation>显示此帮助。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Show the version.</source>
        <translation>显示版本。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>QCanBus plugin, e.g. socketcan or virtualcan.</source>
        <translation>QCanBus 插件，例如 socketcan 或 virtualcan。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>plugin</source>
        <translation>插件</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>CAN interface, e.g. can0 or tcp://127.0.0.1:35468/can0.</source>
        <translation>CAN 接口，例如 can0 或 tcp://127.0.0.1:35468/can0。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>interface</source>
        <translation>接口</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Node ids of joint 1, 2, ..., up to 127 (default: joint j is node j).</source>
        <translation>关节 1、2……的节点 ID，最大 127（默认：关节 j 为节点 j）。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>ids</source>
        <translation>ID</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Scenario file (default: the paper scenario).</source>
        <translation>场景文件（默认：论文场景）。</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+6"/>
        <source>file</source>
        <translation>文件</translation>
    </message>
    <message>
        <location line="-3"/>
        <source>JSON file of the nodes&apos; stored parameters, written at start and after every store.</source>
        <translation>节点已存储参数的 JSON 文件，在启动时及每次存储后写入。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Fault: lose this fraction (0 to 1) of the TPDOs.</source>
        <translation>故障：丢失此比例（0 到 1）的 TPDO。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>F</source>
        <translation>F</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Fault: send nothing at all after N frames.</source>
        <translation>故障：N 帧之后完全停止发送。</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+18"/>
        <source>N</source>
        <translation>N</translation>
    </message>
    <message>
        <location line="-15"/>
        <source>Fault: the first node faults with EMCY 0x8611 at the K-th SYNC in Operation enabled.</source>
        <translation>故障：第一个节点在运行使能状态下的第 K 个 SYNC 时以 EMCY 0x8611 报故障。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>K</source>
        <translation>K</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Fault: SDO writes to this object abort with 0x08000020.</source>
        <translation>故障：对此对象的 SDO 写入以 0x08000020 中止。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>IDX:SUB</source>
        <translation>IDX:SUB</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>SYNC periods in Operation enabled without a set-point before a drive faults with EMCY 0x8100 (default: 3 periods, at least 50 ms).</source>
        <translation>驱动器在 Operation enabled 状态下无设定值多少个 SYNC 周期后以 EMCY 0x8100 报故障（默认：3 个周期，至少 50 ms）。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Drives that were never commissioned: 0x2400 is 0 (by default joint j&apos;s drive holds the robot&apos;s identity and j).</source>
        <translation>从未调试过的驱动器：0x2400 为 0（默认情况下关节 j 的驱动器保存机器人标识和 j）。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The arm starts without the scenario&apos;s payload. A line &apos;mount&apos; on stdin mounts it, &apos;unmount&apos; takes it off (as a technician does around a payload session&apos;s baseline trials).</source>
        <translation>机械臂启动时不带场景的负载。stdin 上的一行 &apos;mount&apos; 安装负载，&apos;unmount&apos; 卸下负载（如技术人员在负载会话的基准试验前后所做）。</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>unexpected argument &apos;%1&apos;</source>
        <translation>意外的参数 &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>--can-plugin is required (available: %1)</source>
        <translation>必须给出 --can-plugin（可用：%1）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>--can-plugin: unknown plugin &apos;%1&apos; (available: %2)</source>
        <translation>--can-plugin：未知插件 &apos;%1&apos;（可用：%2）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>--can-interface is required, e.g. can0 or tcp://127.0.0.1:35468/can0</source>
        <translation>必须给出 --can-interface，例如 can0 或 tcp://127.0.0.1:35468/can0</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>--drop-fraction: &apos;%1&apos; is not a fraction from 0 to 1</source>
        <translation>--drop-fraction：&apos;%1&apos; 不是 0 到 1 之间的比例</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>--emcy-at-sample: &apos;%1&apos; is too large</source>
        <translation>--emcy-at-sample：&apos;%1&apos; 过大</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>--setpoint-timeout: &apos;%1&apos; is too large (at most 100000)</source>
        <translation>--setpoint-timeout：&apos;%1&apos; 过大（最多 100000）</translation>
    </message>
</context>
<context>
    <name>learnid::ApplyConfirmDialog</name>
    <message>
        <location filename="../ui/ApplyConfirmDialog.cpp" line="+16"/>
        <source>Apply parameters to the robot</source>
        <translation>将参数写入机器人</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Write estimate %1 to the robot controller? The controller&apos;s feedforward changes at once.</source>
        <translation>将估计 %1 写入机器人控制器？控制器的前馈将立即改变。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Parameter</source>
        <translation>参数</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>On robot</source>
        <translation>机器人当前值</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>New</source>
        <translation>新值</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Change</source>
        <translation>变化</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Apply to robot</source>
        <translation>写入机器人</translation>
    </message>
</context>
<context>
    <name>learnid::ApplyPanel</name>
    <message>
        <location filename="../ui/ApplyPanel.cpp" line="+23"/>
        <source>estimate </source>
        <translation>估计 </translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Choose:</source>
        <translation>选择：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Accepted:</source>
        <translation>已接受：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Robot holds:</source>
        <translation>机器人参数：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>nothing applied yet</source>
        <translation>尚未写入</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>estimate %1</source>
        <translation>估计 %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>none</source>
        <translation>无</translation>
    </message>
</context>
<context>
    <name>learnid::CanConnection</name>
    <message>
        <location filename="../core/canrobot/CanConnection.cpp" line="+34"/>
        <source>the CAN device %1 did not connect within %2 ms (is the bus or the robot side running?)</source>
        <translation>CAN 设备 %1 未在 %2 ms 内连接（总线或机器人端是否在运行？）</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>no CAN device for %1</source>
        <translation>没有用于 %1 的 CAN 设备</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>cannot connect the CAN device %1: %2</source>
        <translation>无法连接 CAN 设备 %1：%2</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>no error reported (the other side may have exited)</source>
        <translation>未报告错误（对端可能已退出）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the CAN device %1 went unconnected: %2</source>
        <translation>CAN 设备 %1 已断开连接：%2</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>the CAN device %1 reported an error frame: %2</source>
        <translation>CAN 设备 %1 报告了错误帧：%2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the CAN device %1 reported %2 (error frame 0x%3 %4)</source>
        <translation>CAN 设备 %1 报告 %2（错误帧 0x%3 %4）</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>the CAN interface %1 of %2 disappeared</source>
        <translation>%2 的 CAN 接口 %1 已消失</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the CAN interface %1 of %2 went down (ip link set %1 up brings it back)</source>
        <translation>%2 的 CAN 接口 %1 已停用（ip link set %1 up 可重新启用）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the CAN controller of %1 (%2) is %3</source>
        <translation>%1 (%2) 的 CAN 控制器处于 %3</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>the CAN device %1 reports bus off</source>
        <translation>CAN 设备 %1 报告总线关闭 (bus off)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the CAN device %1 reports error passive</source>
        <translation>CAN 设备 %1 报告错误被动</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>the CAN device %1 reported a %2 error: %3</source>
        <translation>CAN 设备 %1 报告了%2错误：%3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>read</source>
        <translation>读取</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>write</source>
        <translation>写入</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the CAN device %1 reported a connection error: %2</source>
        <translation>CAN 设备 %1 报告连接错误：%2</translation>
    </message>
</context>
<context>
    <name>learnid::CanLink</name>
    <message>
        <location filename="../core/can/CanLink.cpp" line="+24"/>
        <source>The CAN device no longer exists.</source>
        <translation>CAN 设备已不存在。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The CAN device %1 is not connected.</source>
        <translation>CAN 设备 %1 未连接。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The CAN device refused the frame: %1</source>
        <translation>CAN 设备拒绝了该帧：%1</translation>
    </message>
</context>
<context>
    <name>learnid::CanRobotWorker</name>
    <message>
        <location filename="../core/canrobot/CanRobotWorker.cpp" line="+111"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>the model has %1 joints but %2 CAN nodes are configured, or the plan is empty</source>
        <translation>模型有 %1 个关节，但配置了 %2 个 CAN 节点，或计划为空</translation>
    </message>
    <message>
        <location line="+16"/>
        <location line="+57"/>
        <source>stopped by the operator before the drives moved</source>
        <translation>在驱动器运动前被操作员停止</translation>
    </message>
    <message>
        <location line="-52"/>
        <source>refused before any motion: %1</source>
        <translation>在任何运动之前被拒绝：%1</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>reading the drives&apos; identity failed: %1</source>
        <translation>读取驱动器标识失败：%1</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>configuring the drives failed, nothing moved: %1</source>
        <translation>配置驱动器失败，未发生任何运动：%1</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>the trial&apos;s candump log could not be written: %1</source>
        <translation>无法写入该试验的 candump 日志：%1</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>%1; the stored parameters are unchanged</source>
        <translation>%1；已存储参数未改变</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1; nothing was stored (%2 not written)</source>
        <translation>%1；未存储任何内容（未写入 %2）</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1; nothing was stored (0x1010 not written)</source>
        <translation>%1；未存储任何内容（未写入 0x1010）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1; storing stopped at node %2 of the list</source>
        <translation>%1；存储在列表中的节点 %2 处停止</translation>
    </message>
</context>
<context>
    <name>learnid::CandumpReplayDevice</name>
    <message>
        <location filename="../core/canrobot/CandumpReplayDevice.cpp" line="+88"/>
        <source>Cannot write a frame: the replay is not connected.</source>
        <translation>无法写入帧：回放未连接。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The master wrote %1 after the end of the log.</source>
        <translation>主站在日志结束后写入了 %1。</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>The master wrote %1 where the log holds %2 (log frame %3): the replayed trial differs from the recorded one.</source>
        <translation>主站写入了 %1，而日志此处为 %2（日志帧 %3）：回放的试验与记录的不同。</translation>
    </message>
</context>
<context>
    <name>learnid::CommissioningSession</name>
    <message>
        <location filename="../core/session/CommissioningSession.cpp" line="+23"/>
        <source>unknown estimator law &apos;%1&apos; (known: %2)</source>
        <translation>未知估计律 &apos;%1&apos;（已知：%2）</translation>
    </message>
    <message>
        <location line="+64"/>
        <source>trial %1 refused before motion: %2</source>
        <translation>试验 %1 在运动前被拒绝：%2</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>repetition %1 of %2: %3</source>
        <translation>第 %1 次重复（共 %2 次）：%3</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>trial %1 stopped at the tracking limit after %2 s: too short to learn from once the filter has settled (%3 s); the estimate is unchanged</source>
        <translation>试验 %1 在 %2 s 后于跟踪误差限值处停止：除去滤波器的稳定时间（%3 s）后太短，无法学习；估计保持不变</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>trial %1 stopped at the tracking limit: its %2 s before the stop observe no parameter; the estimate is unchanged</source>
        <translation>试验 %1 在跟踪误差限值处停止：停止前的 %2 s 观测不到任何参数；估计保持不变</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>the update produced non-finite parameters</source>
        <translation>更新产生了非有限参数</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>trial %1 not learned from: %2</source>
        <translation>未从试验 %1 学习：%2</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>there is no learned estimate to accept yet: run a trial first</source>
        <translation>尚无可接受的学习估计：请先运行一次试验</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>estimate %1 does not exist: choose 1 to %2</source>
        <translation>估计 %1 不存在：请选择 1 到 %2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>only URDF robots have standard parameters to make consistent</source>
        <translation>只有 URDF 机器人有可使其一致的标准参数</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no consistent estimate near estimate %1: %2</source>
        <translation>估计 %1 附近没有一致的估计：%2</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>nothing accepted: accept an estimate before applying it</source>
        <translation>未接受任何估计：请先接受估计再写入</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>nothing to revert: no parameter set has been applied in this session</source>
        <translation>无可撤销内容：本会话中尚未写入任何参数组</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the robot held no parameter set before the first apply; there is nothing to restore</source>
        <translation>首次写入前机器人没有参数组；无可恢复内容</translation>
    </message>
</context>
<context>
    <name>learnid::ConvergenceChart</name>
    <message>
        <location filename="../ui/ConvergenceChart.cpp" line="+32"/>
        <source>Estimate k</source>
        <translation>估计 k</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>|error| [%]</source>
        <translation>|误差| [%]</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>change [%]</source>
        <translation>变化 [%]</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>path torque [%]</source>
        <translation>路径力矩 [%]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Convergence to the truth</source>
        <translation>向真值收敛</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Convergence</source>
        <translation>收敛</translation>
    </message>
    <message>
        <location line="+62"/>
        <source>vs truth</source>
        <translation>相对真值</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>vs newest estimate</source>
        <translation>相对最新估计</translation>
    </message>
</context>
<context>
    <name>learnid::ConvergencePanel</name>
    <message>
        <location filename="../ui/ConvergencePanel.cpp" line="+41"/>
        <source>Estimates</source>
        <translation>估计</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameters</source>
        <translation>参数</translation>
    </message>
</context>
<context>
    <name>learnid::ConvergenceTableModel</name>
    <message>
        <location filename="../ui/ConvergenceTableModel.cpp" line="+195"/>
        <source>all (rank %1)</source>
        <translation>全部（秩 %1）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>⚠ kept %1 of %2</source>
        <translation>⚠ 保留 %2 个中的 %1 个</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>⚠ kept: %1</source>
        <translation>⚠ 保留：%1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1 (learned from a partial trial)</source>
        <translation>%1（从部分试验中学习）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>accepted</source>
        <translation>已接受</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>on robot</source>
        <translation>已写入机器人</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>%1 = %2 ± %3 (1 sigma)</source>
        <translation>%1 = %2 ± %3（1 sigma）</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Estimate</source>
        <translation>估计</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Rel. change [%]</source>
        <translation>相对变化 [%]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Max |e| [deg]</source>
        <translation>最大 |e| [度]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>cond(WᵀW)</source>
        <translation>cond(WᵀW)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Observable</source>
        <translation>可观测</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 vs truth [%]</source>
        <translation>%1 相对真值 [%]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Path torque vs truth [%]</source>
        <translation>路径力矩相对真值 [%]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Trials run</source>
        <translation>已运行试验</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>State</source>
        <translation>状态</translation>
    </message>
</context>
<context>
    <name>learnid::FileController</name>
    <message>
        <location filename="../ui/FileController.cpp" line="+39"/>
        <source>Parameter file written: %1</source>
        <translation>参数文件已写入：%1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Parameter file not written: %1</source>
        <translation>参数文件未写入：%1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Identified URDF written: %1</source>
        <translation>辨识后的 URDF 已写入：%1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>URDF not written: %1</source>
        <translation>URDF 未写入：%1</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Open scenario</source>
        <translation>打开场景</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Scenario files (*.json);;All files (*)</source>
        <translation>场景文件 (*.json);;所有文件 (*)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save scenario</source>
        <translation>保存场景</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Scenario files (*.json)</source>
        <translation>场景文件 (*.json)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export parameter file</source>
        <translation>导出参数文件</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameter files (*.json)</source>
        <translation>参数文件 (*.json)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Folder for the trial CSV files</source>
        <translation>试验 CSV 文件的文件夹</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export plot</source>
        <translation>导出图表</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>PNG image (*.png);;SVG drawing (*.svg)</source>
        <translation>PNG 图像 (*.png);;SVG 矢量图 (*.svg)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PNG image (*.png)</source>
        <translation>PNG 图像 (*.png)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export commissioning report</source>
        <translation>导出调试报告</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
    <message>
        <location line="+84"/>
        <source>Scenario loaded: %1</source>
        <translation>场景已加载：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Scenario not loaded: %1</source>
        <translation>场景未加载：%1</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+8"/>
        <source>Scenario not saved: %1</source>
        <translation>场景未保存：%1</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>Scenario saved: %1</source>
        <translation>场景已保存：%1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Parameter file not written: accept an estimate first</source>
        <translation>参数文件未写入：请先接受一个估计</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>No trial CSV written: no trial has run yet</source>
        <translation>未写入试验 CSV：尚未运行任何试验</translation>
    </message>
    <message numerus="yes">
        <location line="-156"/>
        <source>%n trial CSV file(s) written to %1</source>
        <translation>
            <numerusform>已将 %n 个试验 CSV 文件写入 %1</numerusform>
        </translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Trial CSV not written: %1</source>
        <translation>试验 CSV 未写入：%1</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>Export identified URDF</source>
        <translation>导出辨识后的 URDF</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>URDF (*.urdf)</source>
        <translation>URDF (*.urdf)</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>URDF not written: accept an estimate first</source>
        <translation>URDF 未写入：请先接受一个估计</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>identified by learnid %1 (estimate %2 of a commissioning session) on %3</source>
        <translation>由 learnid %1（调试会话的估计 %2）于 %3 辨识</translation>
    </message>
    <message>
        <location line="+79"/>
        <source>Plot not written: this build has no SVG support (Qt6::Svg); export as PNG instead</source>
        <translation>图表未写入：此版本不支持 SVG（Qt6::Svg），请导出为 PNG</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Tracking error</source>
        <translation>跟踪误差</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Plot written: %1</source>
        <translation>图表已写入：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Plot not written: %1</source>
        <translation>图表未写入：%1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Report not written: no session</source>
        <translation>报告未写入：没有会话</translation>
    </message>
    <message>
        <location filename="../ui/ReportContent.cpp" line="+36"/>
        <source>Path: from (%1, %2) m, %3 m at %4 deg</source>
        <translation>路径：从 (%1, %2) m 起，长 %3 m，方向 %4 度</translation>
    </message>
    <message numerus="yes">
        <location line="+6"/>
        <source>Path: %n joint waypoint(s)</source>
        <translation>
            <numerusform>路径：%n 个关节路点</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Path: %1</source>
        <translation>路径：%1</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Torque limits: %1 N m, planning fraction %2</source>
        <translation>力矩限值：%1 N m，规划比例 %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>kp: %1 N m/rad; ki: %2</source>
        <translation>kp：%1 N m/rad；ki：%2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>kd: %1 N m s/rad; lambda %2 rad/s</source>
        <translation>kd：%1 N m s/rad；lambda %2 rad/s</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Feedforward: model torque at the middle of each %1 ms sample</source>
        <translation>前馈：每个 %1 ms 采样周期中点的模型力矩</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Feedforward: model torque at each %1 ms sample&apos;s instant</source>
        <translation>前馈：每个 %1 ms 采样时刻的模型力矩</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Estimator: %1, rho %2 rad/s, %3 trials</source>
        <translation>估计器：%1，rho %2 rad/s，%3 次试验</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Initial parameters: %1</source>
        <translation>初始参数：%1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>none (nothing applied in this session)</source>
        <translation>无（本次会话未写入）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (estimate %2)</source>
        <translation>%1（估计 %2）</translation>
    </message>
    <message>
        <location filename="../ui/FileController.cpp" line="+8"/>
        <source>Report written: %1</source>
        <translation>报告已写入：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Report not written: %1</source>
        <translation>报告未写入：%1</translation>
    </message>
</context>
<context>
    <name>learnid::LogExportController</name>
    <message>
        <location filename="../ui/LogExportController.cpp" line="+75"/>
        <source>identify and accept a result first</source>
        <translation>请先辨识并接受一个结果</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+6"/>
        <source>Parameter file not written: %1</source>
        <translation>参数文件未写入：%1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Parameter file written: %1</source>
        <translation>参数文件已写入：%1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>URDF not written: identify and accept a result first</source>
        <translation>URDF 未写入：请先辨识并接受一个结果</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>identified by learnid %1 (Identify from recorded data) on %2</source>
        <translation>由 learnid %1（根据记录的数据辨识）于 %2 辨识</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>URDF written: %1</source>
        <translation>URDF 已写入：%1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>URDF not written: %1</source>
        <translation>URDF 未写入：%1</translation>
    </message>
</context>
<context>
    <name>learnid::LogValidationTableModel</name>
    <message>
        <location filename="../ui/LogValidationTableModel.cpp" line="+101"/>
        <source>sqrt(sum e^2 / sum tau^2) over the joints and samples, in %</source>
        <translation>对所有关节和采样点计算的 sqrt(sum e^2 / sum tau^2)，单位 %</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The mean over the joints of RMS error / RMS measured, in %</source>
        <translation>各关节 RMS 误差 / RMS 测量值的平均，单位 %</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>overall %</source>
        <translation>总体 %</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>mean ratio %</source>
        <translation>平均比值 %</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Joint</source>
        <translation>关节</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>RMS measured
[N m]</source>
        <translation>RMS 测量值
[N m]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>URDF as given
RMS error [N m]</source>
        <translation>给定的 URDF
RMS 误差 [N m]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>URDF as given
ratio %</source>
        <translation>给定的 URDF
比值 %</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Identified
RMS error [N m]</source>
        <translation>辨识结果
RMS 误差 [N m]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Identified
ratio %</source>
        <translation>辨识结果
比值 %</translation>
    </message>
</context>
<context>
    <name>learnid::MainActions</name>
    <message>
        <location filename="../ui/MainActions.cpp" line="+37"/>
        <source>&amp;Connect robot</source>
        <translation>连接机器人(&amp;C)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Ctrl+K</source>
        <translation>Ctrl+K</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connect to the chosen robot and plan the first trial</source>
        <translation>连接所选机器人并规划第一次试验</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;New session</source>
        <translation>新建会话(&amp;N)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start a new session with the settings of the form (the history is discarded)</source>
        <translation>以表单中的设置开始新会话（历史记录将被丢弃）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Identify from recorded &amp;data…</source>
        <translation>根据记录的数据辨识(&amp;D)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Identify a robot&apos;s parameters from logs its controller recorded</source>
        <translation>根据机器人控制器记录的日志辨识其参数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Learn a &amp;payload…</source>
        <translation>学习负载(&amp;P)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Learn the payload the robot carries with the arm&apos;s model held fixed (simulated robot)</source>
        <translation>在手臂模型保持不变的情况下学习机器人携带的负载（仿真机器人）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Open scenario...</source>
        <translation>打开场景(&amp;O)...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Load a scenario file into the form</source>
        <translation>将场景文件加载到表单</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Save scenario...</source>
        <translation>保存场景(&amp;S)...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save the form&apos;s scenario to a file</source>
        <translation>将表单中的场景保存到文件</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export &amp;parameter file...</source>
        <translation>导出参数文件(&amp;P)...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ctrl+E</source>
        <translation>Ctrl+E</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write the accepted estimate as a parameter file (JSON and DCF)</source>
        <translation>将已接受的估计写为参数文件（JSON 和 DCF）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export identified &amp;URDF...</source>
        <translation>导出辨识后的 URDF(&amp;U)...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write the robot&apos;s URDF with the accepted estimate as real bodies and its friction (URDF robots)</source>
        <translation>写出机器人的 URDF，以已接受的估计作为真实刚体及其摩擦（URDF 机器人）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export trial &amp;CSV...</source>
        <translation>导出试验 CSV(&amp;C)...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ctrl+Shift+E</source>
        <translation>Ctrl+Shift+E</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Write one CSV file per trial</source>
        <translation>每次试验写一个 CSV 文件</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export p&amp;lot...</source>
        <translation>导出图表(&amp;L)...</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Ctrl+Shift+P</source>
        <translation>Ctrl+Shift+P</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save the tracking-error plot as PNG or SVG</source>
        <translation>将跟踪误差图保存为 PNG 或 SVG</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save the tracking-error plot as PNG (SVG needs Qt6::Svg)</source>
        <translation>将跟踪误差图保存为 PNG（SVG 需要 Qt6::Svg）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export &amp;report (PDF)...</source>
        <translation>导出报告 (PDF)(&amp;R)...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write the one-page commissioning report</source>
        <translation>写出一页调试报告</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Quit</source>
        <translation>退出(&amp;Q)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Quit learnid</source>
        <translation>退出 learnid</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Run trial</source>
        <translation>运行试验(&amp;R)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Run the next trial and learn from it</source>
        <translation>运行下一次试验并从中学习</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Run &amp;all</source>
        <translation>全部运行(&amp;A)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Ctrl+F5</source>
        <translation>Ctrl+F5</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Run the scenario&apos;s number of trials</source>
        <translation>运行场景规定次数的试验</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Stop</source>
        <translation>停止(&amp;S)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Shift+F5</source>
        <translation>Shift+F5</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop the running trial safely at the next sample</source>
        <translation>在下一个采样点安全停止当前试验</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A&amp;ccept</source>
        <translation>接受(&amp;C)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Ctrl+Return</source>
        <translation>Ctrl+Return</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Accept the chosen estimate for apply</source>
        <translation>接受所选估计以便写入</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A&amp;pply...</source>
        <translation>写入(&amp;P)...</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Ctrl+Shift+A</source>
        <translation>Ctrl+Shift+A</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write the accepted estimate to the robot controller</source>
        <translation>将已接受的估计写入机器人控制器</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Re&amp;vert</source>
        <translation>恢复(&amp;V)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Ctrl+Shift+Z</source>
        <translation>Ctrl+Shift+Z</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Restore the parameter set the robot held before the last apply</source>
        <translation>恢复上次写入前机器人的参数组</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;About learnid</source>
        <translation>关于 learnid(&amp;A)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Version and licence</source>
        <translation>版本和许可</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>About &amp;Qt</source>
        <translation>关于 &amp;Qt</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Qt version</source>
        <translation>Qt 版本</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>System language</source>
        <translation>系统语言</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>&amp;File</source>
        <translation>文件(&amp;F)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;Robot</source>
        <translation>机器人(&amp;R)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Trials</source>
        <translation>试验(&amp;T)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Parameters</source>
        <translation>参数(&amp;P)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;View</source>
        <translation>视图(&amp;V)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Language</source>
        <translation>语言(&amp;L)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Help</source>
        <translation>帮助(&amp;H)</translation>
    </message>
</context>
<context>
    <name>learnid::MainWindow</name>
    <message>
        <location filename="../ui/MainWindow.cpp" line="+72"/>
        <source>learnid – commissioning</source>
        <translation>learnid – 调试</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Main</source>
        <translation>主工具栏</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Pre-trial check</source>
        <translation>试验前检查</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Run</source>
        <translation>运行</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Accept / apply</source>
        <translation>接受 / 写入</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Robot</source>
        <translation>机器人</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Scenario</source>
        <translation>场景</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Setup</source>
        <translation>设置</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Parameter convergence</source>
        <translation>参数收敛</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>The language changes when learnid is started again.</source>
        <translation>语言将在下次启动 learnid 时切换。</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Dis&amp;connect robot</source>
        <translation>断开机器人(&amp;C)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Connect robot</source>
        <translation>连接机器人(&amp;C)</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Run disabled: %1</source>
        <translation>禁止运行：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no robot</source>
        <translation>无机器人</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Robot: %1 – %2</source>
        <translation>机器人：%1 – %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>busy</source>
        <translation>忙</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>idle</source>
        <translation>空闲</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not connected</source>
        <translation>未连接</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Cannot connect: %1</source>
        <translation>无法连接：%1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>connecting to %1/%2…</source>
        <translation>正在连接 %1/%2…</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Correct the scenario first: %1</source>
        <translation>请先修正场景：%1</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Apply cancelled; the robot is unchanged.</source>
        <translation>已取消写入；机器人未改变。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>About learnid</source>
        <translation>关于 learnid</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&lt;h3&gt;learnid %1&lt;/h3&gt;&lt;p&gt;Learning identification of robot dynamics: a commissioning tool.&lt;/p&gt;&lt;p&gt;Built with Qt %2.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;learnid %1&lt;/h3&gt;&lt;p&gt;机器人动力学的学习辨识：调试工具。&lt;/p&gt;&lt;p&gt;基于 Qt %2 构建。&lt;/p&gt;</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>The payload step needs the CAN bus: disconnect the arm&apos;s session first.</source>
        <translation>负载步骤需要 CAN 总线：请先断开机械臂的会话。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>The robot panel&apos;s choice cannot be used (%1): the payload step runs on the simulated robot.</source>
        <translation>机器人面板的选择无法使用（%1）：负载步骤在仿真机器人上运行。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The scenario has a payload section: its payload is learned here, in the payload step; the arm&apos;s session is not opened with it.</source>
        <translation>该场景含有 payload 部分：其负载在此负载步骤中学习；不会用它打开手臂的会话。</translation>
    </message>
</context>
<context>
    <name>learnid::MemoryCanDevice</name>
    <message>
        <location filename="../core/can/MemoryCanDevice.cpp" line="+27"/>
        <source>The memory CAN device %1 is not attached to a bus.</source>
        <translation>内存 CAN 设备 %1 未连接到总线。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The memory CAN device %1 refused to connect.</source>
        <translation>内存 CAN 设备 %1 拒绝连接。</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Cannot write a frame: the device %1 is not connected.</source>
        <translation>无法写入帧：设备 %1 未连接。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Cannot write an invalid or CAN FD frame: %1.</source>
        <translation>无法写入无效帧或 CAN FD 帧：%1。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Only data and remote request frames can be written.</source>
        <translation>只能写入数据帧和远程请求帧。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The memory CAN device %1 failed to write the frame.</source>
        <translation>内存 CAN 设备 %1 写入帧失败。</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>CAN error frame, error classes 0x%1.</source>
        <translation>CAN 错误帧，错误类别 0x%1。</translation>
    </message>
</context>
<context>
    <name>learnid::MessageBar</name>
    <message>
        <location filename="../ui/MessageBar.cpp" line="+20"/>
        <source>Dismiss</source>
        <translation>关闭</translation>
    </message>
</context>
<context>
    <name>learnid::ObjectDictionary</name>
    <message>
        <location filename="../core/can/ObjectDictionary.cpp" line="+18"/>
        <source>Object %1: %2 is not numeric; use addBytes().</source>
        <translation>对象 %1：%2 不是数值类型；请使用 addBytes()。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Object %1: %2 is numeric; use add().</source>
        <translation>对象 %1：%2 是数值类型；请使用 add()。</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Object %1 is defined twice.</source>
        <translation>对象 %1 被定义了两次。</translation>
    </message>
    <message>
        <location line="+87"/>
        <source>Object %1 holds %2 bytes, not %3.</source>
        <translation>对象 %1 包含 %2 个字节，而不是 %3 个。</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>Object %1 is not in the object dictionary.</source>
        <translation>对象 %1 不在对象字典中。</translation>
    </message>
</context>
<context>
    <name>learnid::ParameterTableModel</name>
    <message>
        <location filename="../ui/ParameterTableModel.cpp" line="+129"/>
        <source>kept</source>
        <translation>保留</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>yes</source>
        <translation>是</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>⚠ kept</source>
        <translation>⚠ 保留</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>✗ no</source>
        <translation>✗ 否</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>⚠ not plausible</source>
        <translation>⚠ 不合理</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>✓</source>
        <translation>✓</translation>
    </message>
    <message>
        <location line="+56"/>
        <source>Link / joint</source>
        <translation>连杆 / 关节</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Parameter</source>
        <translation>参数</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Unit</source>
        <translation>单位</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Estimate %1</source>
        <translation>估计 %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>σ / |φ| [%]</source>
        <translation>σ / |φ| [%]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Observed</source>
        <translation>已观测</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Real body</source>
        <translation>真实刚体</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Truth</source>
        <translation>真值</translation>
    </message>
</context>
<context>
    <name>learnid::PayloadDialog</name>
    <message>
        <location filename="../ui/PayloadDialog.cpp" line="+50"/>
        <source>&amp;Run trials</source>
        <translation>运行试验(&amp;R)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Stop</source>
        <translation>停止(&amp;S)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Continue</source>
        <translation>继续(&amp;C)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>&amp;Accept</source>
        <translation>接受(&amp;A)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export &amp;parameter file…</source>
        <translation>导出参数文件(&amp;P)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export &amp;URDF…</source>
        <translation>导出 URDF(&amp;U)…</translation>
    </message>
    <message>
        <location filename="../ui/PayloadDialogExport.cpp" line="+48"/>
        <source>Learn a payload (simulated robot)</source>
        <translation>学习负载（仿真机器人）</translation>
    </message>
    <message>
        <location filename="../ui/PayloadDialog.cpp" line="+1"/>
        <source>A&amp;pply to the robot…</source>
        <translation>应用到机器人(&amp;P)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sa&amp;ve scenario…</source>
        <translation>保存场景(&amp;V)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Design &amp;gains for this payload</source>
        <translation>为此负载设计增益(&amp;G)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save report and &amp;trials…</source>
        <translation>保存报告和试验(&amp;T)…</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>Payload and prior</source>
        <translation>负载与先验</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>What the path lets the trials see</source>
        <translation>该路径让试验看到什么</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Trials</source>
        <translation>试验</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Payload estimate</source>
        <translation>负载估计</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Tracking error</source>
        <translation>跟踪误差</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Close</source>
        <translation>关闭</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>The CAN robot %1/%2</source>
        <translation>CAN 机器人 %1/%2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The run asks you to take the payload off before the baseline trials and to mount it after them.</source>
        <translation>运行会要求您在基线试验前取下负载，并在试验后装上。</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>The trials cannot be planned: %1</source>
        <translation>无法规划试验：%1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Trial %1 of %2 running: baseline, without the payload…</source>
        <translation>正在运行第 %1/%2 次试验：基线试验，不带负载…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Trial %1 of %2 running with the payload…</source>
        <translation>正在运行第 %1/%2 次试验，带负载…</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Payload learned: check the estimate, then accept it to apply it to the robot or export it.</source>
        <translation>负载已学习：请检查估计值，然后接受它，以便将其应用到机器人或导出。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Payload learned: check the estimate, then accept it to export.</source>
        <translation>负载已学习：请检查估计值，然后接受以导出。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Payload not learned: %1. The report and trials of the run can be saved (Save report and trials).</source>
        <translation>未学到负载：%1。可以保存本次运行的报告和试验（保存报告和试验）。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Payload not learned: %1</source>
        <translation>负载未学习：%1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Stopped; no payload is kept from this run. Its report and trials can be saved (Save report and trials).</source>
        <translation>已停止；本次运行不保留负载。可以保存其报告和试验（保存报告和试验）。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stopped; nothing of this run is kept or written.</source>
        <translation>已停止；本次运行的任何结果都不会保留或写入。</translation>
    </message>
    <message>
        <location line="+57"/>
        <source>Run the trials to learn the payload.</source>
        <translation>运行试验以学习负载。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Planning the first trial…</source>
        <translation>正在规划第一次试验…</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Correct the payload first: %1</source>
        <translation>请先更正负载：%1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Cannot run: %1</source>
        <translation>无法运行：%1</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Stopping the running trial…</source>
        <translation>正在停止当前试验…</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The baseline trials are done: mount the payload on %1, then press Continue.</source>
        <translation>基线试验已完成：请将负载装到 %1 上，然后按“继续”。</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>Take the payload off %1 for the %n baseline trial(s), then press Continue.</source>
        <translation>
            <numerusform>请为 %n 次基线试验从 %1 上取下负载，然后按“继续”。</numerusform>
        </translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Starting the next trial…</source>
        <translation>正在开始下一次试验…</translation>
    </message>
    <message>
        <location filename="../ui/PayloadDialogExport.cpp" line="-15"/>
        <source>Payload accepted: apply it to the robot&apos;s drives, or export the parameter file or the URDF.</source>
        <translation>负载已接受：将其应用到机器人的驱动器，或导出参数文件或 URDF。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Payload accepted: export the parameter file or the URDF. It is not applied to a robot (the simulated robot carries it already).</source>
        <translation>负载已接受：请导出参数文件或 URDF。它不会应用到机器人上（仿真机器人已携带该负载）。</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Learn a payload (CAN robot %1/%2)</source>
        <translation>学习负载（CAN 机器人 %1/%2）</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Write the payload on %1 (%2 kg, centre of mass (%3, %4, %5) mm) to every drive of %6/%7 (object 0x2500), read it back and store it?</source>
        <translation>将 %1 上的负载（%2 kg，质心 (%3, %4, %5) mm）写入 %6/%7 的每个驱动器（对象 0x2500），回读并存储？</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Apply the payload</source>
        <translation>应用负载</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Apply cancelled; the robot is unchanged.</source>
        <translation>已取消写入；机器人未改变。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Writing the payload to the drives…</source>
        <translation>正在将负载写入驱动器…</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Applied: every drive stored the payload (0x2500).</source>
        <translation>已应用：每个驱动器都已存储负载（0x2500）。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Not applied: %1</source>
        <translation>未应用：%1</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>Export parameter file</source>
        <translation>导出参数文件</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameter files (*.json)</source>
        <translation>参数文件 (*.json)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export URDF with the payload</source>
        <translation>导出带负载的 URDF</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>URDF (*.urdf)</source>
        <translation>URDF (*.urdf)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>learnid %1, %2</source>
        <translation>learnid %1，%2</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Written: %1</source>
        <translation>已写入：%1</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+56"/>
        <source>Not written: %1</source>
        <translation>未写入：%1</translation>
    </message>
    <message>
        <location line="-35"/>
        <source>Gains designed for the arm carrying %1 kg on %2 (planning fraction %3); the preview checks the first trial with them.</source>
        <translation>已为在 %2 上承载 %1 kg 的机械臂设计增益（规划比例 %3）；预览会用它们检查第一次试验。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the tip link</source>
        <translation>末端连杆</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Gains not designed: %1</source>
        <translation>未设计增益：%1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Save the run&apos;s report and trials</source>
        <translation>保存本次运行的报告和试验</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Payload reports (*.json)</source>
        <translation>负载报告 (*.json)</translation>
    </message>
    <message numerus="yes">
        <location line="+10"/>
        <source>Written: %1 and %n trial CSV(s) in %2</source>
        <translation>
            <numerusform>已写入：%1 以及 %2 中的 %n 个试验 CSV</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>Written: %1 and %n trial CSV(s) in %2, of a run that ended early: %3</source>
        <translation>
            <numerusform>已写入：%1 以及 %2 中的 %n 个试验 CSV，来自一次提前结束的运行：%3</numerusform>
        </translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Save scenario</source>
        <translation>保存场景</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Scenario files (*.json)</source>
        <translation>场景文件 (*.json)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Scenario saved: %1</source>
        <translation>场景已保存：%1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Scenario not saved: %1</source>
        <translation>场景未保存：%1</translation>
    </message>
</context>
<context>
    <name>learnid::PayloadEstimateTableModel</name>
    <message>
        <location filename="../ui/PayloadEstimateTableModel.cpp" line="+86"/>
        <source>data (the trials)</source>
        <translation>数据（试验）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>prior (not identified)</source>
        <translation>先验（未辨识）</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Value</source>
        <translation>量</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Unit</source>
        <translation>单位</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Estimate</source>
        <translation>估计值</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Std. error</source>
        <translation>标准误差</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Prior</source>
        <translation>先验</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>From</source>
        <translation>来源</translation>
    </message>
</context>
<context>
    <name>learnid::PayloadForm</name>
    <message>
        <location filename="../ui/PayloadForm.cpp" line="+42"/>
        <location line="+91"/>
        <source>Scenario key %1</source>
        <translation>场景键 %1</translation>
    </message>
    <message>
        <location line="-85"/>
        <source>Mounted on link</source>
        <translation>安装在连杆</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Mass (prior)</source>
        <translation>质量（先验）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>the technician&apos;s estimate</source>
        <translation>技术人员的估计</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Centre of mass (prior) x, y, z</source>
        <translation>质心（先验）x, y, z</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Inertia about it (prior) Ixx, Ixy, Iyy, Ixz, Iyz, Izz</source>
        <translation>绕质心的惯量（先验）Ixx, Ixy, Iyy, Ixz, Iyz, Izz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>empty: a solid sphere</source>
        <translation>留空：实心球</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Bound: sphere around the flange, radius</source>
        <translation>边界：以法兰为中心的球，半径</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>or a box x0, y0, z0, x1, y1, z1</source>
        <translation>或长方体 x0, y0, z0, x1, y1, z1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>empty: the sphere</source>
        <translation>留空：使用球</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Baseline trials without the payload</source>
        <translation>不带负载的基线试验</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Payload trials</source>
        <translation>负载试验</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>the tip (%1)</source>
        <translation>末端（%1）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 (on %2)</source>
        <translation>%1（位于 %2）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 is fixed to %2 and moves with it</source>
        <translation>%1 固定在 %2 上并随其运动</translation>
    </message>
    <message>
        <location line="+71"/>
        <location line="+3"/>
        <source>enter one number</source>
        <translation>请输入一个数</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>enter %1 numbers, got %2</source>
        <translation>请输入 %1 个数，实际为 %2 个</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>enter %1 numbers</source>
        <translation>请输入 %1 个数</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>enter a whole number</source>
        <translation>请输入整数</translation>
    </message>
</context>
<context>
    <name>learnid::PayloadRunJob</name>
    <message>
        <location filename="../core/service/PayloadRunJob.cpp" line="+92"/>
        <source>the run&apos;s robot is no longer connected: run again</source>
        <translation>该次运行的机器人已不再连接：请重新运行</translation>
    </message>
    <message>
        <location line="+96"/>
        <source>stopped (Stop) by the technician</source>
        <translation>由技术人员停止（停止）</translation>
    </message>
</context>
<context>
    <name>learnid::PayloadTrialTableModel</name>
    <message>
        <location filename="../ui/PayloadTrialTableModel.cpp" line="+68"/>
        <source>kept for the payload trials</source>
        <translation>保留用于负载试验</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>all</source>
        <translation>全部</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>none (the prior)</source>
        <translation>无（先验）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>all but %1</source>
        <translation>除 %1 外全部</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>baseline</source>
        <translation>基线</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>payload, stopped</source>
        <translation>负载，已停止</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>payload</source>
        <translation>负载</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>A baseline trial runs the same timed path without the payload</source>
        <translation>基线试验在不带负载的情况下运行同一定时路径</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The worst joint&apos;s maximum tracking error</source>
        <translation>最差关节的最大跟踪误差</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The worst joint&apos;s RMS tracking error</source>
        <translation>最差关节的 RMS 跟踪误差</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The payload fitted to the trials so far</source>
        <translation>根据目前试验拟合的负载</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CPU time of the payload&apos;s update</source>
        <translation>负载更新的 CPU 时间</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The payload&apos;s values the trials so far identified; the others keep the prior</source>
        <translation>目前试验已辨识的负载量；其余保持先验值</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Trial</source>
        <translation>试验</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Kind</source>
        <translation>类型</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Max [deg]</source>
        <translation>最大 [°]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>RMS [deg]</source>
        <translation>RMS [°]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Mass [kg]</source>
        <translation>质量 [kg]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CoM [mm]</source>
        <translation>质心 [mm]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Update [ms]</source>
        <translation>更新 [ms]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Identified</source>
        <translation>已辨识</translation>
    </message>
</context>
<context>
    <name>learnid::PreTrialCheckView</name>
    <message>
        <location filename="../ui/PreTrialCheckView.cpp" line="+38"/>
        <source>Joint</source>
        <translation>关节</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Peak [N m]</source>
        <translation>峰值 [N m]</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Limit [N m]</source>
        <translation>限值 [N m]</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Use</source>
        <translation>占用</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Gravity</source>
        <translation>重力</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The largest torque holding the arm against gravity takes on this path, as a share of the limit</source>
        <translation>在该路径上克服重力保持机械臂所需的最大力矩，占限值的比例</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Planned motion:</source>
        <translation>规划运动：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Closed loop:</source>
        <translation>闭环：</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Connect a robot to plan the first trial.</source>
        <translation>连接机器人以规划第一次试验。</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Trial %1: check passed, the trial may run.</source>
        <translation>试验 %1：检查通过，可以运行。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Trial %1 refused: %2</source>
        <translation>试验 %1 被拒绝：%2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>no plan</source>
        <translation>无规划</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 s motion, %2 s with rests, %3 samples</source>
        <translation>运动 %1 s，含静止 %2 s，%3 个采样</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>estimate not physical (mass matrix not positive definite)</source>
        <translation>估计不符合物理（质量矩阵非正定）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>stable: max |z| = %1, decay rate %2 1/s</source>
        <translation>稳定：max |z| = %1，衰减率 %2 1/s</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>UNSTABLE: max |z| = %1 at t = %2 s (growth %3 1/s)</source>
        <translation>不稳定：max |z| = %1，t = %2 s（增长 %3 1/s）</translation>
    </message>
</context>
<context>
    <name>learnid::RecordedDataDialog</name>
    <message>
        <location filename="../ui/RecordedDataDialog.cpp" line="+46"/>
        <source>&amp;Identify</source>
        <translation>辨识(&amp;I)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&amp;Accept</source>
        <translation>接受(&amp;A)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export &amp;parameter file…</source>
        <translation>导出参数文件(&amp;P)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export &amp;URDF…</source>
        <translation>导出 URDF(&amp;U)…</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Identify from recorded data</source>
        <translation>根据记录的数据辨识</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>Not identified: %1</source>
        <translation>未辨识：%1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Identification cancelled; nothing was identified or written.</source>
        <translation>辨识已取消；未辨识或写入任何内容。</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Robot and logs</source>
        <translation>机器人和日志</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Fit</source>
        <translation>拟合</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Validation on:</source>
        <translation>验证所用日志：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Validation</source>
        <translation>验证</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Predicted against measured torque (validation log)</source>
        <translation>预测力矩与测量力矩对比（验证日志）</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Close</source>
        <translation>关闭</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>Add the robot&apos;s logs and press Identify.</source>
        <translation>添加机器人的日志，然后点击“辨识”。</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Cannot identify: %1</source>
        <translation>无法辨识：%1</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Cancelling after the current step…</source>
        <translation>将在当前步骤完成后取消…</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>Result accepted: export the parameter file or the URDF.</source>
        <translation>结果已接受：可导出参数文件或 URDF。</translation>
    </message>
</context>
<context>
    <name>learnid::RecordedDataForm</name>
    <message>
        <location filename="../ui/RecordedDataForm.cpp" line="+42"/>
        <source>Robot logs (*.csv);;All files (*)</source>
        <translation>机器人日志 (*.csv);;所有文件 (*)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Robot URDF</source>
        <translation>机器人 URDF</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>URDF (*.urdf);;All files (*)</source>
        <translation>URDF (*.urdf);;所有文件 (*)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Logs to identify from</source>
        <translation>用于辨识的日志</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Logs to validate on</source>
        <translation>用于验证的日志</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Scenario with the controller gains</source>
        <translation>包含控制器增益的场景</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Scenario files (*.json);;All files (*)</source>
        <translation>场景文件 (*.json);;所有文件 (*)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Export parameter file</source>
        <translation>导出参数文件</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameter files (*.json)</source>
        <translation>参数文件 (*.json)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export URDF</source>
        <translation>导出 URDF</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>URDF (*.urdf)</source>
        <translation>URDF (*.urdf)</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+5"/>
        <source>Browse…</source>
        <translation>浏览…</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 (built-in URDF)</source>
        <translation>%1（内置 URDF）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>URDF file…</source>
        <translation>URDF 文件…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the robot&apos;s URDF file</source>
        <translation>机器人的 URDF 文件</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The logs&apos; column names as learnid-cli identify --columns takes them: t=, q=, dq=, tau= with %1 for the joint number. Empty: t, q%1, dq%1, tau%1.</source>
        <translation>日志的列名，格式与 learnid-cli identify --columns 相同：t=、q=、dq=、tau=，用 %1 表示关节编号。留空：t、q%1、dq%1、tau%1。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>none: the parameter file holds the model alone</source>
        <translation>无：参数文件仅包含模型</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A scenario of this robot whose controller gains the parameter file records; the logs do not say which gains they were recorded with.</source>
        <translation>此机器人的一个场景，其控制器增益将记录在参数文件中；日志本身不说明记录时所用的增益。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>armature</source>
        <translation>转子惯量</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>viscous</source>
        <translation>粘性</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Coulomb</source>
        <translation>库仑</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>offset</source>
        <translation>偏置</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Robot:</source>
        <translation>机器人：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Training logs:</source>
        <translation>训练日志：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Validation logs:</source>
        <translation>验证日志：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Columns:</source>
        <translation>列：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Joint terms:</source>
        <translation>关节项：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gains from:</source>
        <translation>增益来源：</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Add…</source>
        <translation>添加…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove</source>
        <translation>移除</translation>
    </message>
    <message>
        <location line="+109"/>
        <source>choose the robot&apos;s URDF file</source>
        <translation>请选择机器人的 URDF 文件</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>add at least one training log (the logs to identify from)</source>
        <translation>请至少添加一个训练日志（用于辨识的日志）</translation>
    </message>
</context>
<context>
    <name>learnid::ReportWriter</name>
    <message>
        <location filename="../ui/ReportWriter.cpp" line="+56"/>
        <source>Parameters</source>
        <translation>参数</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>learnid commissioning report</source>
        <translation>learnid 调试报告</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Commissioning report</source>
        <translation>调试报告</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Robot: %1</source>
        <translation>机器人：%1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Scenario</source>
        <translation>场景</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Parameter convergence</source>
        <translation>参数收敛</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Applied set: %1</source>
        <translation>已写入参数组：%1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>learnid %1</source>
        <translation>learnid %1</translation>
    </message>
</context>
<context>
    <name>learnid::RobotChooser</name>
    <message>
        <location filename="../ui/RobotChooser.cpp" line="+36"/>
        <source>Robot model</source>
        <translation>机器人模型</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Open URDF…</source>
        <translation>打开 URDF…</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>The paper&apos;s 2-link arm (closed form)</source>
        <translation>论文中的两连杆臂（闭式）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 (built-in URDF)</source>
        <translation>%1（内置 URDF）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>URDF file…</source>
        <translation>URDF 文件…</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Joint</source>
        <translation>关节</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Lower</source>
        <translation>下限</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Upper</source>
        <translation>上限</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Effort</source>
        <translation>最大力矩/力</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Mass [kg]</source>
        <translation>质量 [kg]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Position limits in deg (revolute) or m (prismatic), effort in N m or N, as the URDF gives them; the mass of the link the joint moves</source>
        <translation>位置限值单位为 deg（旋转关节）或 m（移动关节），最大力矩/力（effort）单位为 N m 或 N，均取自 URDF；质量为该关节所驱动连杆的质量</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Open the robot&apos;s URDF</source>
        <translation>打开机器人的 URDF</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>URDF (*.urdf);;All files (*)</source>
        <translation>URDF (*.urdf);;所有文件 (*)</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>Cannot use this robot: %1</source>
        <translation>无法使用此机器人：%1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>2 revolute joints in the horizontal plane, no gravity or friction; %1 parameters (the paper&apos;s a, b, c)</source>
        <translation>水平面内 2 个旋转关节，无重力和摩擦；%1 个参数（论文中的 a、b、c）</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 (prismatic)</source>
        <translation>%1（移动关节）</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>rotor inertia</source>
        <translation>转子惯量</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>viscous</source>
        <translation>粘性</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Coulomb</source>
        <translation>库仑</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>offset</source>
        <translation>偏置</translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%n revolute joint(s)</source>
        <translation>
            <numerusform>%n 个旋转关节</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n joint(s) (%1 prismatic)</source>
        <translation>
            <numerusform>%n 个关节（其中 %1 个移动关节）</numerusform>
        </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1, %2 kg moving; joint terms: %3; %4 base parameters (of %5 standard)</source>
        <translation>%1，运动质量 %2 kg；关节项：%3；%4 个基参数（共 %5 个标准参数）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Warning: %1</source>
        <translation>警告：%1</translation>
    </message>
</context>
<context>
    <name>learnid::RobotPanel</name>
    <message>
        <location filename="../ui/RobotPanel.cpp" line="+24"/>
        <source>First commissioning: I confirmed each node&apos;s joint on the arm</source>
        <translation>首次调试：我已在机械臂上确认每个节点对应的关节</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+109"/>
        <source>Connect</source>
        <translation>连接</translation>
    </message>
    <message>
        <location line="-99"/>
        <source>Simulated (the scenario&apos;s robot)</source>
        <translation>仿真（场景中的机器人）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAN (CANopen / CiA 402)</source>
        <translation>CAN（CANopen / CiA 402）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>QCanBus plugin: socketcan for a CAN adapter on Linux; virtualcan to try learnid-robot-sim first</source>
        <translation>QCanBus 插件：Linux 下的 CAN 适配器用 socketcan；先试用 learnid-robot-sim 用 virtualcan</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>e.g. can0 (socketcan) or tcp://127.0.0.1:35468/can0 (virtualcan)</source>
        <translation>例如 can0（socketcan）或 tcp://127.0.0.1:35468/can0（virtualcan）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CANopen node id of joint 1, 2, ... (docs/can-protocol.md)</source>
        <translation>关节 1、2……的 CANopen 节点 ID（docs/can-protocol.md）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>10 SYNC periods, at least 50 ms</source>
        <translation>10 个 SYNC 周期，至少 50 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> ms</source>
        <translation> 毫秒</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A trial stops when no SYNC arrives for this long</source>
        <translation>若超过此时间未收到 SYNC，试验即停止</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Only for drives never commissioned (or taken from another robot): tick it after checking on the arm that the drive of each node (its serial number on the type plate) moves the joint the node is listed for. Apply then stores the joint identity in the drives, and later sessions check it without this (docs/can-protocol.md 2.4).</source>
        <translation>仅用于从未调试过（或取自另一台机器人）的驱动器：请先在机械臂上确认每个节点的驱动器（铭牌上的序列号）驱动的正是该节点所列的关节，然后再勾选。应用时会将关节标识存入驱动器，之后的会话无需勾选即可检查（docs/can-protocol.md 2.4）。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Plugin:</source>
        <translation>插件：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Interface:</source>
        <translation>接口：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Nodes:</source>
        <translation>节点：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SYNC timeout:</source>
        <translation>SYNC 超时：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drives:</source>
        <translation>驱动器：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Robot:</source>
        <translation>机器人：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>State:</source>
        <translation>状态：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not connected</source>
        <translation>未连接</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>CAN nodes: %1</source>
        <translation>CAN 节点：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CAN nodes: %1 node ids for a robot of %2 joints: one node per joint</source>
        <translation>CAN 节点：%1 个节点 ID，而机器人有 %2 个关节：每个关节一个节点</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>CAN interface: enter one, e.g. can0</source>
        <translation>CAN 接口：请输入一个，例如 can0</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Disconnect</source>
        <translation>断开</translation>
    </message>
</context>
<context>
    <name>learnid::RunPanel</name>
    <message>
        <location filename="../ui/RunPanel.cpp" line="+27"/>
        <source>%p %</source>
        <translation>%p %</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%v of %m trials</source>
        <translation>%v / %m 次试验</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Trial:</source>
        <translation>试验：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Series:</source>
        <translation>系列：</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>trial %1: %p %</source>
        <translation>试验 %1：%p %</translation>
    </message>
</context>
<context>
    <name>learnid::ScenarioFields</name>
    <message>
        <location filename="../ui/ScenarioFields.cpp" line="+82"/>
        <source>Start (x, y)</source>
        <translation>起点 (x, y)</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>Number of trials</source>
        <translation>试验次数</translation>
    </message>
    <message>
        <location line="-26"/>
        <source>Length</source>
        <translation>长度</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Direction</source>
        <translation>方向</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Rest before the motion</source>
        <translation>运动前静止时间</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Rest after the motion</source>
        <translation>运动后静止时间</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Torque limits</source>
        <translation>力矩限值</translation>
    </message>
    <message>
        <location line="-28"/>
        <source>Limit per joint</source>
        <translation>各关节限值</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Path</source>
        <translation>路径</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Planning fraction</source>
        <translation>规划比例</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Gentle first trials</source>
        <translation>温和的首批试验</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Gentle trials&apos; speed</source>
        <translation>温和试验的速度</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Controller</source>
        <translation>控制器</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>lambda (derivative filter)</source>
        <translation>lambda（微分滤波）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Estimator</source>
        <translation>估计器</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>rho (filter F)</source>
        <translation>rho（滤波器 F）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Rank tolerance</source>
        <translation>秩容差</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Repetitions per trial</source>
        <translation>每次试验的重复次数</translation>
    </message>
    <message>
        <location line="-56"/>
        <source>Initial parameters</source>
        <translation>初始参数</translation>
    </message>
    <message>
        <location line="+63"/>
        <source>Safety</source>
        <translation>安全</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Abort at tracking error</source>
        <translation>跟踪误差中止阈值</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Required stability margin</source>
        <translation>所需稳定裕度</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Simulated robot</source>
        <translation>仿真机器人</translation>
    </message>
    <message>
        <location line="-67"/>
        <source>True parameters</source>
        <translation>真实参数</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>Torque sensor lag</source>
        <translation>力矩传感器滞后</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>CAD perturbation (URDF robots)</source>
        <translation>CAD 扰动（URDF 机器人）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Encoder counts per revolution (0: ideal)</source>
        <translation>编码器每转计数（0：理想）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Torque noise (fraction of limit)</source>
        <translation>力矩噪声（占限值的比例）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Noise seed</source>
        <translation>噪声种子</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>RK4 steps per sample</source>
        <translation>每个采样的 RK4 步数</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>enter a value</source>
        <translation>请输入数值</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>&quot;%1&quot; is not a number</source>
        <translation>“%1”不是数字</translation>
    </message>
</context>
<context>
    <name>learnid::ScenarioForm</name>
    <message>
        <location filename="../ui/ScenarioForm.cpp" line="+64"/>
        <location line="+30"/>
        <source>Scenario key %1</source>
        <translation>场景键 %1</translation>
    </message>
    <message>
        <location line="-28"/>
        <source>URDF robots: empty takes the robot&apos;s</source>
        <translation>URDF 机器人：留空则采用机器人的值</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>values separated by commas</source>
        <translation>用逗号分隔的数值</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>paper-consistent</source>
        <translation>与论文一致</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>improved (zero-phase, WLS)</source>
        <translation>改进（零相位，WLS）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Estimator law</source>
        <translation>学习律</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the drives (motor current)</source>
        <translation>驱动器（电机电流）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>joint torque sensors behind the gears</source>
        <translation>减速器后的关节力矩传感器</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Torque measured by</source>
        <translation>力矩测量来源</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>unknown model &quot;%1&quot;</source>
        <translation>未知模型“%1”</translation>
    </message>
    <message numerus="yes">
        <location line="+32"/>
        <source>Initial parameters (%n base parameter(s))</source>
        <translation>
            <numerusform>初始参数（%n 个基参数）</numerusform>
        </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Initial parameters (%1)</source>
        <translation>初始参数（%1）</translation>
    </message>
    <message>
        <location line="+13"/>
        <location line="+112"/>
        <source>robot.model: %1</source>
        <translation>robot.model：%1</translation>
    </message>
    <message>
        <location line="-78"/>
        <source>path.file: %1</source>
        <translation>path.file：%1</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>enter one number</source>
        <translation>请输入一个数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>enter %1 numbers, got %2</source>
        <translation>请输入 %1 个数，实际 %2 个</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>enter a whole number</source>
        <translation>请输入整数</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>enter a whole number from %1 to %2</source>
        <translation>请输入 %1 到 %2 之间的整数</translation>
    </message>
</context>
<context>
    <name>learnid::SdoClient</name>
    <message>
        <location filename="../core/can/SdoClient.cpp" line="+132"/>
        <source>%1 is not a valid CANopen node id (1 to 127).</source>
        <translation>%1 不是有效的 CANopen 节点 ID（1 到 127）。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>There are no data to write.</source>
        <translation>没有要写入的数据。</translation>
    </message>
    <message>
        <location line="+34"/>
        <location line="+23"/>
        <source>The answer names another object.</source>
        <translation>应答指向了另一个对象。</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>The node announced %1 bytes but sent %2%3.</source>
        <translation>节点声明 %1 个字节，但发送了 %2%3。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source> or more</source>
        <translation> 或更多</translation>
    </message>
    <message>
        <location line="+55"/>
        <source>SDO read of %1 from node %2</source>
        <translation>从节点 %2 SDO 读取 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SDO write of %1 to node %2</source>
        <translation>向节点 %2 SDO 写入 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> (abort code %1)</source>
        <translation>（中止代码 %1）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The %1 was refused by the node%2: %3</source>
        <translation>%1 被节点拒绝%2：%3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The %1 was aborted%2: %3</source>
        <translation>%1 已中止%2：%3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The %1 failed: %2</source>
        <translation>%1 失败：%2</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>node %1 did not answer within %2 ms.</source>
        <translation>节点 %1 未在 %2 ms 内应答。</translation>
    </message>
</context>
<context>
    <name>learnid::SessionPresenter</name>
    <message>
        <location filename="../ui/SessionPresenter.cpp" line="+35"/>
        <source>connected: %1</source>
        <translation>已连接：%1</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+5"/>
        <source>not connected</source>
        <translation>未连接</translation>
    </message>
    <message>
        <location line="-4"/>
        <source>Cannot start the session: %1</source>
        <translation>无法启动会话：%1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Connect a robot to plan the first trial.</source>
        <translation>连接机器人以规划第一次试验。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Trial %1 running…</source>
        <translation>试验 %1 运行中…</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Trial %1 stopped: %2. Learned from its first %3 s (a partial trial); the next trial runs with the new estimate.</source>
        <translation>试验 %1 已停止：%2。已从其前 %3 s 学习（部分试验）；下一次试验使用新的估计运行。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Trial %1: %2.</source>
        <translation>试验 %1：%2。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Trial %1 %2: %3. Its data are kept.</source>
        <translation>试验 %1 %2：%3。其数据已保留。</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Finished; %1 estimate(s) learned.</source>
        <translation>完成；已学习 %1 个估计。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stopped; see the message above.</source>
        <translation>已停止；请查看上方消息。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Estimate %1 accepted.</source>
        <translation>已接受估计 %1。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Parameters written to the robot and read back.</source>
        <translation>参数已写入机器人并回读确认。</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/ApplyPreview.cpp" line="+21"/>
        <source>%n parameter(s)</source>
        <translation>
            <numerusform>%n 个参数</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/SessionPresenter.cpp" line="+26"/>
        <source>nothing applied yet</source>
        <translation>尚未写入</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (estimate %2)</source>
        <translation>%1（估计 %2）</translation>
    </message>
</context>
<context>
    <name>learnid::SessionWorker</name>
    <message>
        <location filename="../core/service/SessionWorker.cpp" line="+46"/>
        <source>payload: the arm&apos;s session does not learn a payload; learn it in the payload step (Robot &gt; Learn a payload) or with learnid-cli run --scenario FILE</source>
        <translation>payload：手臂的会话不学习负载；请在负载步骤中学习（机器人 &gt; 学习负载），或使用 learnid-cli run --scenario FILE</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>unknown robot model &quot;%1&quot;</source>
        <translation>未知机器人模型“%1”</translation>
    </message>
    <message>
        <location line="+111"/>
        <location line="+26"/>
        <source>no robot connected</source>
        <translation>未连接机器人</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>no session to export</source>
        <translation>没有可导出的会话</translation>
    </message>
</context>
<context>
    <name>learnid::TorqueFitPlot</name>
    <message>
        <location filename="../ui/TorqueFitPlot.cpp" line="+93"/>
        <source>Identify to see the predicted against the measured torque.</source>
        <translation>辨识后即可查看预测力矩与测量力矩的对比。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Time [s]</source>
        <translation>时间 [s]</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>measured</source>
        <translation>测量值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>identified</source>
        <translation>辨识结果</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>URDF as given</source>
        <translation>给定的 URDF</translation>
    </message>
    <message>
        <location line="+83"/>
        <source>All joints</source>
        <translation>所有关节</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Joint %1 [N m]</source>
        <translation>关节 %1 [N m]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Joint %1</source>
        <translation>关节 %1</translation>
    </message>
</context>
<context>
    <name>learnid::TrackingErrorPlot</name>
    <message>
        <location filename="../ui/TrackingErrorPlot.cpp" line="+31"/>
        <source>Auto-scale</source>
        <translation>自动缩放</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The joint whose tracking error is shown</source>
        <translation>显示其跟踪误差的关节</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Off: symmetric axis on a 0.02 deg grid, as in the paper</source>
        <translation>关闭：对称坐标轴，0.02 度网格，与论文相同</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Time [s]</source>
        <translation>时间 [s]</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../ui/TrackingErrorStyle.cpp" line="+94"/>
        <source>Tracking error [deg]</source>
        <translation>跟踪误差 [度]</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Show:</source>
        <translation>显示：</translation>
    </message>
    <message>
        <location line="+26"/>
        <location line="+63"/>
        <source>All trials (overlay)</source>
        <translation>所有试验（叠加）</translation>
    </message>
    <message>
        <location line="-39"/>
        <source>All joints</source>
        <translation>所有关节</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Trial %1</source>
        <translation>试验 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Trial %1 (%2)</source>
        <translation>试验 %1（%2）</translation>
    </message>
    <message>
        <location line="+97"/>
        <source>Tracking error</source>
        <translation>跟踪误差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tracking error of %1</source>
        <translation>%1 的跟踪误差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1, all trials (darker: later)</source>
        <translation>%1，所有试验（颜色越深越晚）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1, %2</source>
        <translation>%1，%2</translation>
    </message>
    <message>
        <location filename="../ui/TrackingErrorStyle.cpp" line="-41"/>
        <location line="+18"/>
        <source>Joint %1</source>
        <translation>关节 %1</translation>
    </message>
    <message>
        <location line="-17"/>
        <source>Joint %1 (%2)</source>
        <translation>关节 %1（%2）</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>Error [deg]</source>
        <translation>误差 [deg]</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>[deg]</source>
        <translation>[deg]</translation>
    </message>
</context>
<context>
    <name>learnid::TrialStreamer</name>
    <message>
        <location filename="../core/canrobot/TrialStreamer.cpp" line="+32"/>
        <location line="+94"/>
        <location line="+68"/>
        <location filename="../core/canrobot/TrialStreamerSteps.cpp" line="+49"/>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <location line="-149"/>
        <source>%1 did not reach Operation enabled within %2 ms: it reports %3 (statusword 0x%4)</source>
        <translation>%1 未在 %2 ms 内达到运行使能：报告为 %3（状态字 0x%4）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>no TPDO</source>
        <translation>无 TPDO</translation>
    </message>
    <message>
        <location line="+80"/>
        <source>stopped by the operator %1</source>
        <translation>被操作员停止 %1</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>%1: %2 %3</source>
        <translation>%1：%2 %3</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1 left Operation enabled: it reports %2 (0x6041 = 0x%3) %4</source>
        <translation>%1 离开了运行使能：报告为 %2（0x6041 = 0x%3）%4</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>tracking error of %1 reached %2 deg (limit %3 deg) %4: quick stop</source>
        <translation>%1 的跟踪误差达到 %2 度（限值 %3 度）%4：快速停止</translation>
    </message>
    <message>
        <location line="+71"/>
        <source>only %1 of %2 samples were recorded</source>
        <translation>%2 个采样点中只记录了 %1 个</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>an unknown node</source>
        <translation>未知节点</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>node %1 (joint %2)</source>
        <translation>节点 %1（关节 %2）</translation>
    </message>
</context>
<context>
    <name>learnid::TrialWatchdog</name>
    <message>
        <location filename="../core/canrobot/TrialWatchdog.cpp" line="+25"/>
        <source>no SYNC for %1 ms: the robot side stopped sending</source>
        <translation>%1 ms 内无 SYNC：机器人端已停止发送</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>heartbeat of %1 lost: none for %2 ms (timeout %3 ms)</source>
        <translation>%1 的心跳丢失：%2 ms 内没有心跳（超时 %3 ms）</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 restarted on its own (boot-up message 0x%2)</source>
        <translation>%1 自行重启（boot-up 报文 0x%2）</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>node %1 (joint %2)</source>
        <translation>节点 %1（关节 %2）</translation>
    </message>
</context>
<context>
    <name>learnid::WaypointEditor</name>
    <message>
        <location filename="../ui/WaypointEditor.cpp" line="+19"/>
        <source>Add waypoint</source>
        <translation>添加路点</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove waypoint</source>
        <translation>删除路点</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Path CSV…</source>
        <translation>路径 CSV…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Waypoints</source>
        <translation>路点</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Run a recorded joint path instead: CSV t, q1..qn [s, rad]</source>
        <translation>改为运行记录的关节路径：CSV t, q1..qn [s, rad]</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Open a joint path</source>
        <translation>打开关节路径</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CSV (*.csv);;All files (*)</source>
        <translation>CSV (*.csv);;所有文件 (*)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Joint positions the path passes through, in order: degrees for revolute joints, metres for prismatic ones</source>
        <translation>路径依次经过的关节位置：旋转关节以度为单位，移动关节以米为单位</translation>
    </message>
    <message>
        <location line="+56"/>
        <source>q%1 [%2]</source>
        <translation>q%1 [%2]</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>m</source>
        <translation>m</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>deg</source>
        <translation>deg</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Path: %1 (%2 samples)</source>
        <translation>路径：%1（%2 个采样点）</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>waypoint %1, %2: &quot;%3&quot; is not a number</source>
        <translation>路点 %1，%2：“%3”不是数字</translation>
    </message>
</context>
<context>
    <name>learnid::robotsim::SimProcess</name>
    <message>
        <location filename="../app/robot-sim/SimProcess.cpp" line="+44"/>
        <source>learnid-robot-sim: stopping (%1)</source>
        <translation>learnid-robot-sim：正在停止（%1）</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+101"/>
        <source>cannot connect the CAN interface %1 with plugin %2: %3</source>
        <translation>无法用插件 %2 连接 CAN 接口 %1：%3</translation>
    </message>
    <message>
        <location line="-67"/>
        <location line="+17"/>
        <location line="+80"/>
        <source>learnid-robot-sim: error: %1</source>
        <translation>learnid-robot-sim：错误：%1</translation>
    </message>
    <message>
        <location line="-90"/>
        <source>learnid-robot-sim: error: cannot create the CAN device %1 with plugin %2: %3</source>
        <translation>learnid-robot-sim：错误：无法用插件 %2 创建 CAN 设备 %1：%3</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>learnid-robot-sim: error: --payload-off: the scenario has no payload section</source>
        <translation>learnid-robot-sim：错误：--payload-off：场景没有 payload 部分</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+58"/>
        <source>learnid-robot-sim: error: --state: %1</source>
        <translation>learnid-robot-sim：错误：--state：%1</translation>
    </message>
    <message>
        <location line="-51"/>
        <source>learnid-robot-sim: silent after %1 frames (injected fault)</source>
        <translation>learnid-robot-sim：%1 帧后静默（注入故障）</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>the CAN device %1 disconnected</source>
        <translation>CAN 设备 %1 已断开</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>learnid-robot-sim: CAN device error: %1</source>
        <translation>learnid-robot-sim：CAN 设备错误：%1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the CAN interface %1 with plugin %2 did not connect within %3 s</source>
        <translation>使用插件 %2 的 CAN 接口 %1 未在 %3 s 内连接</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>learnid-robot-sim: unknown command &apos;%1&apos; on stdin (mount, unmount)</source>
        <translation>learnid-robot-sim：stdin 上的未知命令 &apos;%1&apos;（mount、unmount）</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>learnid-robot-sim: %1: the scenario has no payload section</source>
        <translation>learnid-robot-sim：%1：场景没有 payload 部分</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/gui/StartOptions.cpp" line="+67"/>
        <source>Commissioning tool: learning identification of robot dynamics.</source>
        <translation>调试工具：机器人动力学的学习辨识。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The window needs a display; learnid-cli works without one.</source>
        <translation>窗口需要显示器；learnid-cli 无需显示器即可使用。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Run a simulated session, save the window as PNG to &lt;file&gt; and exit.</source>
        <translation>运行一次仿真会话，将窗口保存为 PNG 到 &lt;file&gt; 后退出。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>User interface language, e.g. de or zh_CN (default: as chosen in the app, else the system&apos;s).</source>
        <translation>界面语言，例如 de 或 zh_CN（默认：应用中选择的语言，否则为系统语言）。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>What --screenshot shows: %1 (default: main).</source>
        <translation>--screenshot 显示的内容：%1（默认：main）。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Open the scenario &lt;file&gt; at start.</source>
        <translation>启动时打开场景 &lt;file&gt;。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>A scenario file to open at start (as --scenario).</source>
        <translation>启动时打开的场景文件（同 --scenario）。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>learnid: unknown --screenshot-view &apos;%1&apos;; known: %2</source>
        <translation>learnid：未知的 --screenshot-view &apos;%1&apos;；已知：%2</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>learnid: one scenario at a time, got %1: %2</source>
        <translation>learnid：一次只能打开一个场景，收到 %1 个：%2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>learnid: the window needs a display, and none is set (DISPLAY, WAYLAND_DISPLAY); learnid --help lists the options, learnid-cli works without a display.</source>
        <translation>learnid：窗口需要显示器，但未设置（DISPLAY、WAYLAND_DISPLAY）；learnid --help 列出选项，learnid-cli 无需显示器即可使用。</translation>
    </message>
</context>
</TS>

<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>learnid::ApplyConfirmDialog</name>
    <message>
        <source>Apply parameters to the robot</source>
        <translation>将参数写入机器人</translation>
    </message>
    <message>
        <source>Write estimate %1 to the robot controller? The controller's feedforward changes at once.</source>
        <translation>将估计 %1 写入机器人控制器？控制器的前馈将立即改变。</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>参数</translation>
    </message>
    <message>
        <source>On robot</source>
        <translation>机器人当前值</translation>
    </message>
    <message>
        <source>New</source>
        <translation>新值</translation>
    </message>
    <message>
        <source>Change</source>
        <translation>变化</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>Apply to robot</source>
        <translation>写入机器人</translation>
    </message>
</context>
<context>
    <name>learnid::ApplyPanel</name>
    <message>
        <source>estimate </source>
        <translation>估计 </translation>
    </message>
    <message>
        <source>Choose:</source>
        <translation>选择：</translation>
    </message>
    <message>
        <source>Accepted:</source>
        <translation>已接受：</translation>
    </message>
    <message>
        <source>Robot holds:</source>
        <translation>机器人参数：</translation>
    </message>
    <message>
        <source>nothing applied yet</source>
        <translation>尚未写入</translation>
    </message>
    <message>
        <source>estimate %1</source>
        <translation>估计 %1</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
</context>
<context>
    <name>learnid::ConvergenceChart</name>
    <message>
        <source>Estimate k</source>
        <translation>估计 k</translation>
    </message>
    <message>
        <source>|error| [%]</source>
        <translation>|误差| [%]</translation>
    </message>
    <message>
        <source>change [%]</source>
        <translation>变化 [%]</translation>
    </message>
    <message>
        <source>Convergence to the truth</source>
        <translation>向真值收敛</translation>
    </message>
    <message>
        <source>Convergence</source>
        <translation>收敛</translation>
    </message>
</context>
<context>
    <name>learnid::ConvergenceTableModel</name>
    <message>
        <source>all (rank %1)</source>
        <translation>全部（秩 %1）</translation>
    </message>
    <message>
        <source>⚠ kept: %1</source>
        <translation>⚠ 保留：%1</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <source>accepted</source>
        <translation>已接受</translation>
    </message>
    <message>
        <source>on robot</source>
        <translation>已写入机器人</translation>
    </message>
    <message>
        <source>%1 = %2 ± %3 (1 sigma)</source>
        <translation>%1 = %2 ± %3（1 sigma）</translation>
    </message>
    <message>
        <source>Estimate</source>
        <translation>估计</translation>
    </message>
    <message>
        <source>Rel. change [%]</source>
        <translation>相对变化 [%]</translation>
    </message>
    <message>
        <source>Max |e| [deg]</source>
        <translation>最大 |e| [度]</translation>
    </message>
    <message>
        <source>cond(WᵀW)</source>
        <translation>cond(WᵀW)</translation>
    </message>
    <message>
        <source>Observable</source>
        <translation>可观测</translation>
    </message>
    <message>
        <source>%1 vs truth [%]</source>
        <translation>%1 相对真值 [%]</translation>
    </message>
    <message>
        <source>Trials run</source>
        <translation>已运行试验</translation>
    </message>
    <message>
        <source>State</source>
        <translation>状态</translation>
    </message>
</context>
<context>
    <name>learnid::FileController</name>
    <message>
        <source>Parameter file written: %1</source>
        <translation>参数文件已写入：%1</translation>
    </message>
    <message>
        <source>Parameter file not written: %1</source>
        <translation>参数文件未写入：%1</translation>
    </message>
    <message>
        <source>Open scenario</source>
        <translation>打开场景</translation>
    </message>
    <message>
        <source>Scenario files (*.json);;All files (*)</source>
        <translation>场景文件 (*.json);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Save scenario</source>
        <translation>保存场景</translation>
    </message>
    <message>
        <source>Scenario files (*.json)</source>
        <translation>场景文件 (*.json)</translation>
    </message>
    <message>
        <source>Export parameter file</source>
        <translation>导出参数文件</translation>
    </message>
    <message>
        <source>Parameter files (*.json)</source>
        <translation>参数文件 (*.json)</translation>
    </message>
    <message>
        <source>Folder for the trial CSV files</source>
        <translation>试验 CSV 文件的文件夹</translation>
    </message>
    <message>
        <source>Export plot</source>
        <translation>导出图表</translation>
    </message>
    <message>
        <source>PNG image (*.png);;SVG drawing (*.svg)</source>
        <translation>PNG 图像 (*.png);;SVG 矢量图 (*.svg)</translation>
    </message>
    <message>
        <source>PNG image (*.png)</source>
        <translation>PNG 图像 (*.png)</translation>
    </message>
    <message>
        <source>Export commissioning report</source>
        <translation>导出调试报告</translation>
    </message>
    <message>
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Scenario loaded: %1</source>
        <translation>场景已加载：%1</translation>
    </message>
    <message>
        <source>Scenario not loaded: %1</source>
        <translation>场景未加载：%1</translation>
    </message>
    <message>
        <source>Scenario not saved: %1</source>
        <translation>场景未保存：%1</translation>
    </message>
    <message>
        <source>Scenario saved: %1</source>
        <translation>场景已保存：%1</translation>
    </message>
    <message>
        <source>Parameter file not written: accept an estimate first</source>
        <translation>参数文件未写入：请先接受一个估计</translation>
    </message>
    <message>
        <source>No trial CSV written: no trial has run yet</source>
        <translation>未写入试验 CSV：尚未运行任何试验</translation>
    </message>
    <message>
        <source>cannot create the folder %1</source>
        <translation>无法创建文件夹 %1</translation>
    </message>
    <message numerus="yes">
        <source>%n trial CSV file(s) written to %1</source>
        <translation>
            <numerusform>已将 %n 个试验 CSV 文件写入 %1</numerusform></translation>
    </message>
    <message>
        <source>Trial CSV not written: %1</source>
        <translation>试验 CSV 未写入：%1</translation>
    </message>
    <message>
        <source>Plot not written: this build has no SVG support (Qt6::Svg); export as PNG instead</source>
        <translation>图表未写入：此版本不支持 SVG（Qt6::Svg），请导出为 PNG</translation>
    </message>
    <message>
        <source>Tracking error</source>
        <translation>跟踪误差</translation>
    </message>
    <message>
        <source>Plot written: %1</source>
        <translation>图表已写入：%1</translation>
    </message>
    <message>
        <source>Plot not written: %1</source>
        <translation>图表未写入：%1</translation>
    </message>
    <message>
        <source>Report not written: no session</source>
        <translation>报告未写入：没有会话</translation>
    </message>
    <message>
        <source>Path: from (%1, %2) m, %3 m at %4 deg</source>
        <translation>路径：从 (%1, %2) m 起，长 %3 m，方向 %4 度</translation>
    </message>
    <message>
        <source>Torque limits: %1 N m, planning fraction %2</source>
        <translation>力矩限值：%1 N m，规划比例 %2</translation>
    </message>
    <message>
        <source>kp: %1 N m/rad; ki: %2</source>
        <translation>kp：%1 N m/rad；ki：%2</translation>
    </message>
    <message>
        <source>kd: %1 N m s/rad; lambda %2 rad/s</source>
        <translation>kd：%1 N m s/rad；lambda %2 rad/s</translation>
    </message>
    <message>
        <source>Estimator: %1, rho %2 rad/s, %3 trials</source>
        <translation>估计器：%1，rho %2 rad/s，%3 次试验</translation>
    </message>
    <message>
        <source>Initial parameters: %1</source>
        <translation>初始参数：%1</translation>
    </message>
    <message>
        <source>none (nothing applied in this session)</source>
        <translation>无（本次会话未写入）</translation>
    </message>
    <message>
        <source>%1 (estimate %2)</source>
        <translation>%1（估计 %2）</translation>
    </message>
    <message>
        <source>Report written: %1</source>
        <translation>报告已写入：%1</translation>
    </message>
    <message>
        <source>Report not written: %1</source>
        <translation>报告未写入：%1</translation>
    </message>
</context>
<context>
    <name>learnid::MainActions</name>
    <message>
        <source>&amp;Connect robot</source>
        <translation>连接机器人(&amp;C)</translation>
    </message>
    <message>
        <source>Ctrl+K</source>
        <translation>Ctrl+K</translation>
    </message>
    <message>
        <source>Connect to the chosen robot and plan the first trial</source>
        <translation>连接所选机器人并规划第一次试验</translation>
    </message>
    <message>
        <source>&amp;New session</source>
        <translation>新建会话(&amp;N)</translation>
    </message>
    <message>
        <source>Start a new session with the settings of the form (the history is discarded)</source>
        <translation>以表单中的设置开始新会话（历史记录将被丢弃）</translation>
    </message>
    <message>
        <source>&amp;Open scenario...</source>
        <translation>打开场景(&amp;O)...</translation>
    </message>
    <message>
        <source>Load a scenario file into the form</source>
        <translation>将场景文件加载到表单</translation>
    </message>
    <message>
        <source>&amp;Save scenario...</source>
        <translation>保存场景(&amp;S)...</translation>
    </message>
    <message>
        <source>Save the form's scenario to a file</source>
        <translation>将表单中的场景保存到文件</translation>
    </message>
    <message>
        <source>Export &amp;parameter file...</source>
        <translation>导出参数文件(&amp;P)...</translation>
    </message>
    <message>
        <source>Ctrl+E</source>
        <translation>Ctrl+E</translation>
    </message>
    <message>
        <source>Write the accepted estimate as a parameter file (JSON and DCF)</source>
        <translation>将已接受的估计写为参数文件（JSON 和 DCF）</translation>
    </message>
    <message>
        <source>Export trial &amp;CSV...</source>
        <translation>导出试验 CSV(&amp;C)...</translation>
    </message>
    <message>
        <source>Ctrl+Shift+E</source>
        <translation>Ctrl+Shift+E</translation>
    </message>
    <message>
        <source>Write one CSV file per trial</source>
        <translation>每次试验写一个 CSV 文件</translation>
    </message>
    <message>
        <source>Export p&amp;lot...</source>
        <translation>导出图表(&amp;L)...</translation>
    </message>
    <message>
        <source>Ctrl+Shift+P</source>
        <translation>Ctrl+Shift+P</translation>
    </message>
    <message>
        <source>Save the tracking-error plot as PNG or SVG</source>
        <translation>将跟踪误差图保存为 PNG 或 SVG</translation>
    </message>
    <message>
        <source>Save the tracking-error plot as PNG (SVG needs Qt6::Svg)</source>
        <translation>将跟踪误差图保存为 PNG（SVG 需要 Qt6::Svg）</translation>
    </message>
    <message>
        <source>Export &amp;report (PDF)...</source>
        <translation>导出报告 (PDF)(&amp;R)...</translation>
    </message>
    <message>
        <source>Write the one-page commissioning report</source>
        <translation>写出一页调试报告</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>退出(&amp;Q)</translation>
    </message>
    <message>
        <source>Quit learnid</source>
        <translation>退出 learnid</translation>
    </message>
    <message>
        <source>&amp;Run trial</source>
        <translation>运行试验(&amp;R)</translation>
    </message>
    <message>
        <source>Run the next trial and learn from it</source>
        <translation>运行下一次试验并从中学习</translation>
    </message>
    <message>
        <source>Run &amp;all</source>
        <translation>全部运行(&amp;A)</translation>
    </message>
    <message>
        <source>Ctrl+F5</source>
        <translation>Ctrl+F5</translation>
    </message>
    <message>
        <source>Run the scenario's number of trials</source>
        <translation>运行场景规定次数的试验</translation>
    </message>
    <message>
        <source>&amp;Stop</source>
        <translation>停止(&amp;S)</translation>
    </message>
    <message>
        <source>Shift+F5</source>
        <translation>Shift+F5</translation>
    </message>
    <message>
        <source>Stop the running trial safely at the next sample</source>
        <translation>在下一个采样点安全停止当前试验</translation>
    </message>
    <message>
        <source>A&amp;ccept</source>
        <translation>接受(&amp;C)</translation>
    </message>
    <message>
        <source>Ctrl+Return</source>
        <translation>Ctrl+Return</translation>
    </message>
    <message>
        <source>Accept the chosen estimate for apply</source>
        <translation>接受所选估计以便写入</translation>
    </message>
    <message>
        <source>A&amp;pply...</source>
        <translation>写入(&amp;P)...</translation>
    </message>
    <message>
        <source>Ctrl+Shift+A</source>
        <translation>Ctrl+Shift+A</translation>
    </message>
    <message>
        <source>Write the accepted estimate to the robot controller</source>
        <translation>将已接受的估计写入机器人控制器</translation>
    </message>
    <message>
        <source>Re&amp;vert</source>
        <translation>恢复(&amp;V)</translation>
    </message>
    <message>
        <source>Ctrl+Shift+Z</source>
        <translation>Ctrl+Shift+Z</translation>
    </message>
    <message>
        <source>Restore the parameter set the robot held before the last apply</source>
        <translation>恢复上次写入前机器人的参数组</translation>
    </message>
    <message>
        <source>&amp;About learnid</source>
        <translation>关于 learnid(&amp;A)</translation>
    </message>
    <message>
        <source>Version and licence</source>
        <translation>版本和许可</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>关于 &amp;Qt</translation>
    </message>
    <message>
        <source>Qt version</source>
        <translation>Qt 版本</translation>
    </message>
    <message>
        <source>System language</source>
        <translation>系统语言</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>文件(&amp;F)</translation>
    </message>
    <message>
        <source>&amp;Robot</source>
        <translation>机器人(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Trials</source>
        <translation>试验(&amp;T)</translation>
    </message>
    <message>
        <source>&amp;Parameters</source>
        <translation>参数(&amp;P)</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>视图(&amp;V)</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>语言(&amp;L)</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>帮助(&amp;H)</translation>
    </message>
</context>
<context>
    <name>learnid::MainWindow</name>
    <message>
        <source>learnid – commissioning</source>
        <translation>learnid – 调试</translation>
    </message>
    <message>
        <source>Main</source>
        <translation>主工具栏</translation>
    </message>
    <message>
        <source>Pre-trial check</source>
        <translation>试验前检查</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>运行</translation>
    </message>
    <message>
        <source>Accept / apply</source>
        <translation>接受 / 写入</translation>
    </message>
    <message>
        <source>Robot</source>
        <translation>机器人</translation>
    </message>
    <message>
        <source>Scenario</source>
        <translation>场景</translation>
    </message>
    <message>
        <source>Setup</source>
        <translation>设置</translation>
    </message>
    <message>
        <source>Parameter convergence</source>
        <translation>参数收敛</translation>
    </message>
    <message>
        <source>The language changes when learnid is started again.</source>
        <translation>语言将在下次启动 learnid 时切换。</translation>
    </message>
    <message>
        <source>Dis&amp;connect robot</source>
        <translation>断开机器人(&amp;C)</translation>
    </message>
    <message>
        <source>&amp;Connect robot</source>
        <translation>连接机器人(&amp;C)</translation>
    </message>
    <message>
        <source>Run disabled: %1</source>
        <translation>禁止运行：%1</translation>
    </message>
    <message>
        <source>no robot</source>
        <translation>无机器人</translation>
    </message>
    <message>
        <source>Robot: %1 – %2</source>
        <translation>机器人：%1 – %2</translation>
    </message>
    <message>
        <source>busy</source>
        <translation>忙</translation>
    </message>
    <message>
        <source>idle</source>
        <translation>空闲</translation>
    </message>
    <message>
        <source>not connected</source>
        <translation>未连接</translation>
    </message>
    <message>
        <source>Correct the scenario first: %1</source>
        <translation>请先修正场景：%1</translation>
    </message>
    <message>
        <source>Apply cancelled; the robot is unchanged.</source>
        <translation>已取消写入；机器人未改变。</translation>
    </message>
    <message>
        <source>About learnid</source>
        <translation>关于 learnid</translation>
    </message>
    <message>
        <source>&lt;h3&gt;learnid %1&lt;/h3&gt;&lt;p&gt;Learning identification of robot dynamics: a commissioning tool.&lt;/p&gt;&lt;p&gt;Built with Qt %2.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;learnid %1&lt;/h3&gt;&lt;p&gt;机器人动力学的学习辨识：调试工具。&lt;/p&gt;&lt;p&gt;基于 Qt %2 构建。&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>learnid::MessageBar</name>
    <message>
        <source>Dismiss</source>
        <translation>关闭</translation>
    </message>
</context>
<context>
    <name>learnid::PreTrialCheckView</name>
    <message>
        <source>Joint</source>
        <translation>关节</translation>
    </message>
    <message>
        <source>Peak [N m]</source>
        <translation>峰值 [N m]</translation>
    </message>
    <message>
        <source>Limit [N m]</source>
        <translation>限值 [N m]</translation>
    </message>
    <message>
        <source>Use</source>
        <translation>占用</translation>
    </message>
    <message>
        <source>Planned motion:</source>
        <translation>规划运动：</translation>
    </message>
    <message>
        <source>Closed loop:</source>
        <translation>闭环：</translation>
    </message>
    <message>
        <source>Connect a robot to plan the first trial.</source>
        <translation>连接机器人以规划第一次试验。</translation>
    </message>
    <message>
        <source>Trial %1: check passed, the trial may run.</source>
        <translation>试验 %1：检查通过，可以运行。</translation>
    </message>
    <message>
        <source>Trial %1 refused: %2</source>
        <translation>试验 %1 被拒绝：%2</translation>
    </message>
    <message>
        <source>no plan</source>
        <translation>无规划</translation>
    </message>
    <message>
        <source>%1 s motion, %2 s with rests, %3 samples</source>
        <translation>运动 %1 s，含静止 %2 s，%3 个采样</translation>
    </message>
    <message>
        <source>estimate not physical (mass matrix not positive definite)</source>
        <translation>估计不符合物理（质量矩阵非正定）</translation>
    </message>
    <message>
        <source>stable: max |z| = %1, decay rate %2 1/s</source>
        <translation>稳定：max |z| = %1，衰减率 %2 1/s</translation>
    </message>
    <message>
        <source>UNSTABLE: max |z| = %1 at t = %2 s (growth %3 1/s)</source>
        <translation>不稳定：max |z| = %1，t = %2 s（增长 %3 1/s）</translation>
    </message>
</context>
<context>
    <name>learnid::ReportWriter</name>
    <message>
        <source>learnid commissioning report</source>
        <translation>learnid 调试报告</translation>
    </message>
    <message>
        <source>Commissioning report</source>
        <translation>调试报告</translation>
    </message>
    <message>
        <source>Robot: %1</source>
        <translation>机器人：%1</translation>
    </message>
    <message>
        <source>Scenario</source>
        <translation>场景</translation>
    </message>
    <message>
        <source>Parameter convergence</source>
        <translation>参数收敛</translation>
    </message>
    <message>
        <source>Applied set: %1</source>
        <translation>已写入参数组：%1</translation>
    </message>
    <message>
        <source>learnid %1</source>
        <translation>learnid %1</translation>
    </message>
</context>
<context>
    <name>learnid::RobotPanel</name>
    <message>
        <source>Connect</source>
        <translation>连接</translation>
    </message>
    <message>
        <source>Simulated (paper 2-link arm)</source>
        <translation>仿真（论文中的两连杆臂）</translation>
    </message>
    <message>
        <source>CAN (CANopen / CiA 402)</source>
        <translation>CAN（CANopen / CiA 402）</translation>
    </message>
    <message>
        <source>available when the CAN link lands</source>
        <translation>CAN 连接完成后可用</translation>
    </message>
    <message>
        <source>Simulated robot; CAN: %1</source>
        <translation>仿真机器人；CAN：%1</translation>
    </message>
    <message>
        <source>Robot:</source>
        <translation>机器人：</translation>
    </message>
    <message>
        <source>State:</source>
        <translation>状态：</translation>
    </message>
    <message>
        <source>not connected</source>
        <translation>未连接</translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation>断开</translation>
    </message>
</context>
<context>
    <name>learnid::RunPanel</name>
    <message>
        <source>%p %</source>
        <translation>%p %</translation>
    </message>
    <message>
        <source>%v of %m trials</source>
        <translation>%v / %m 次试验</translation>
    </message>
    <message>
        <source>Trial:</source>
        <translation>试验：</translation>
    </message>
    <message>
        <source>Series:</source>
        <translation>系列：</translation>
    </message>
    <message>
        <source>trial %1: %p %</source>
        <translation>试验 %1：%p %</translation>
    </message>
</context>
<context>
    <name>learnid::ScenarioFields</name>
    <message>
        <source>Start (x, y)</source>
        <translation>起点 (x, y)</translation>
    </message>
    <message>
        <source>Number of trials</source>
        <translation>试验次数</translation>
    </message>
    <message>
        <source>Path (straight line)</source>
        <translation>路径（直线）</translation>
    </message>
    <message>
        <source>Length</source>
        <translation>长度</translation>
    </message>
    <message>
        <source>Direction</source>
        <translation>方向</translation>
    </message>
    <message>
        <source>Torque limits</source>
        <translation>力矩限值</translation>
    </message>
    <message>
        <source>Limit per joint</source>
        <translation>各关节限值</translation>
    </message>
    <message>
        <source>Planning fraction</source>
        <translation>规划比例</translation>
    </message>
    <message>
        <source>Controller</source>
        <translation>控制器</translation>
    </message>
    <message>
        <source>lambda (derivative filter)</source>
        <translation>lambda（微分滤波）</translation>
    </message>
    <message>
        <source>Estimator</source>
        <translation>估计器</translation>
    </message>
    <message>
        <source>rho (filter F)</source>
        <translation>rho（滤波器 F）</translation>
    </message>
    <message>
        <source>Initial parameters</source>
        <translation>初始参数</translation>
    </message>
    <message>
        <source>enter a value</source>
        <translation>请输入数值</translation>
    </message>
    <message>
        <source>"%1" is not a number</source>
        <translation>“%1”不是数字</translation>
    </message>
</context>
<context>
    <name>learnid::ScenarioForm</name>
    <message>
        <source>Scenario key %1</source>
        <translation>场景键 %1</translation>
    </message>
    <message>
        <source>values separated by commas</source>
        <translation>用逗号分隔的数值</translation>
    </message>
    <message>
        <source>paper-consistent</source>
        <translation>与论文一致</translation>
    </message>
    <message>
        <source>improved (zero-phase, WLS)</source>
        <translation>改进（零相位，WLS）</translation>
    </message>
    <message>
        <source>Estimator law</source>
        <translation>学习律</translation>
    </message>
    <message>
        <source>Initial parameters (%1)</source>
        <translation>初始参数（%1）</translation>
    </message>
    <message>
        <source>enter one number</source>
        <translation>请输入一个数</translation>
    </message>
    <message>
        <source>enter %1 numbers, got %2</source>
        <translation>请输入 %1 个数，实际 %2 个</translation>
    </message>
    <message>
        <source>enter a whole number</source>
        <translation>请输入整数</translation>
    </message>
</context>
<context>
    <name>learnid::SessionPresenter</name>
    <message>
        <source>connected: %1</source>
        <translation>已连接：%1</translation>
    </message>
    <message>
        <source>not connected</source>
        <translation>未连接</translation>
    </message>
    <message>
        <source>Cannot start the session: %1</source>
        <translation>无法启动会话：%1</translation>
    </message>
    <message>
        <source>Connect a robot to plan the first trial.</source>
        <translation>连接机器人以规划第一次试验。</translation>
    </message>
    <message>
        <source>Trial %1 running…</source>
        <translation>试验 %1 运行中…</translation>
    </message>
    <message>
        <source>Trial %1 %2: %3. Its data are kept.</source>
        <translation>试验 %1 %2：%3。其数据已保留。</translation>
    </message>
    <message>
        <source>Finished; %1 estimate(s) learned.</source>
        <translation>完成；已学习 %1 个估计。</translation>
    </message>
    <message>
        <source>Stopped; see the message above.</source>
        <translation>已停止；请查看上方消息。</translation>
    </message>
    <message>
        <source>Estimate %1 accepted.</source>
        <translation>已接受估计 %1。</translation>
    </message>
    <message>
        <source>Parameters written to the robot and read back.</source>
        <translation>参数已写入机器人并回读确认。</translation>
    </message>
    <message>
        <source>nothing applied yet</source>
        <translation>尚未写入</translation>
    </message>
    <message>
        <source>%1 (estimate %2)</source>
        <translation>%1（估计 %2）</translation>
    </message>
</context>
<context>
    <name>learnid::SessionWorker</name>
    <message>
        <source>unknown robot model "%1"</source>
        <translation>未知机器人模型“%1”</translation>
    </message>
    <message>
        <source>no robot connected</source>
        <translation>未连接机器人</translation>
    </message>
    <message>
        <source>no session to export</source>
        <translation>没有可导出的会话</translation>
    </message>
</context>
<context>
    <name>learnid::TrackingErrorPlot</name>
    <message>
        <source>Auto-scale</source>
        <translation>自动缩放</translation>
    </message>
    <message>
        <source>Off: symmetric axis on a 0.02 deg grid, as in the paper</source>
        <translation>关闭：对称坐标轴，0.02 度网格，与论文相同</translation>
    </message>
    <message>
        <source>Time [s]</source>
        <translation>时间 [s]</translation>
    </message>
    <message>
        <source>Tracking error [deg]</source>
        <translation>跟踪误差 [度]</translation>
    </message>
    <message>
        <source>Show:</source>
        <translation>显示：</translation>
    </message>
    <message>
        <source>All trials (overlay)</source>
        <translation>所有试验（叠加）</translation>
    </message>
    <message>
        <source>Trial %1</source>
        <translation>试验 %1</translation>
    </message>
    <message>
        <source>Trial %1 (%2)</source>
        <translation>试验 %1（%2）</translation>
    </message>
    <message>
        <source>Tracking error, all trials (solid: joint 1, dashed: joint 2; darker: later)</source>
        <translation>跟踪误差，所有试验（实线：关节 1，虚线：关节 2；颜色越深越晚）</translation>
    </message>
    <message>
        <source>Tracking error, %1</source>
        <translation>跟踪误差，%1</translation>
    </message>
    <message>
        <source>trial %1, joint %2</source>
        <translation>试验 %1，关节 %2</translation>
    </message>
    <message>
        <source>joint %1</source>
        <translation>关节 %1</translation>
    </message>
</context>
</TS>

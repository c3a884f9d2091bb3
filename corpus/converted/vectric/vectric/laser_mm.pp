+ Converted by postc from laser_mm.pp (Vectric)
+================================================
+
+ postc corpus: grbl router with a laser (mm).
+
+ Demonstrates:
+ - LASER_SUPPORT: JET_TOOL_ON (M4 with the power), JET_TOOL_POWER (a
+   new S word when the power changes) and JET_TOOL_OFF (M5);
+ - [P] as S0..S1000 from a percentage through a multiplier of 10,
+   printed only when it changes;
+ - SPINDLE_ON (M3 with [S]) after the header and each tool change,
+   never for a jet tool;
+ - arc sections that print [Z]: helices print through them (G2/G3 with
+   Z), there are no helical sections;
+ - FIRST_FEED_MOVE and FIRST_ arc sections carrying [F];
+ - no DWELL_MOVE section: dwells are left out (seed 001), with a
+   warning when posting.
+
+================================================

POST_NAME = "grbl Laser and Spindle (mm) (*.gcode)"
FILE_EXTENSION = "gcode"
UNITS = "MM"
LINE_ENDING = "[10]"
LASER_SUPPORT = "YES"

VAR POWER = [P|C|S|1.0|10]
VAR SPINDLE_SPEED = [S|A|S|1.0]
VAR FEED_RATE = [F|C|F|1.0]
VAR X_POSITION = [X|C|X|1.3]
VAR Y_POSITION = [Y|C|Y|1.3]
VAR Z_POSITION = [Z|C|Z|1.3]
VAR ARC_CENTRE_I_INC_POSITION = [I|A|I|1.3]
VAR ARC_CENTRE_J_INC_POSITION = [J|A|J|1.3]
VAR X_HOME_POSITION = [XH|A|X|1.3]
VAR Y_HOME_POSITION = [YH|A|Y|1.3]
VAR Z_HOME_POSITION = [ZH|A|Z|1.3]

begin HEADER
"; [TP_FILENAME] - [TOOLS_USED]"
"G21 G90 G17"
"G0[ZH]"
"G0[XH][YH]"

begin SPINDLE_ON
"M3[S]"

begin TOOLCHANGE
"M5"
"G0[ZH]"
"; change to tool [T] [TOOLNAME], then resume"
"M0"

begin NEW_SEGMENT
"; [TOOLPATH_NAME]"

begin RAPID_MOVE
"G0[X][Y][Z]"

begin FIRST_FEED_MOVE
"G1[X][Y][Z][F]"

begin FEED_MOVE
"G1[X][Y][Z]"

begin FIRST_CW_ARC_MOVE
"G2[X][Y][Z][I][J][F]"

begin CW_ARC_MOVE
"G2[X][Y][Z][I][J]"

begin FIRST_CCW_ARC_MOVE
"G3[X][Y][Z][I][J][F]"

begin CCW_ARC_MOVE
"G3[X][Y][Z][I][J]"

begin JET_TOOL_ON
"M4[P]"

begin JET_TOOL_POWER
"[P]"

begin JET_TOOL_OFF
"M5"

begin FOOTER
"M5"
"G0[ZH]"
"G0[XH][YH]"
"M2"

+ Converted by postc from gcode_noarcs_mm.pp (Vectric)
+================================================
+
+ postc corpus: G-code WITHOUT arcs, Fanuc style (mm).
+
+ Demonstrates:
+ - a post without arc sections: every arc and helix is linearized into
+   FEED_MOVE segments (equal angles, chord error 0.01 mm);
+ - FEED_RATE_CHANGE printing the feed on a block of its own, so the
+   move sections carry no [F];
+ - the # flag: feeds print with a decimal point (F1200.);
+ - block numbers N10, N20, ... that wrap past LINE_NUMBER_MAXIMUM
+   (990) back to LINE_NUMBER_START;
+ - SPINDLE_SPEED_RANGE: a spindle dial of steps 1..15 for 4500..18000 rpm;
+ - DWELL_MOVE in milliseconds through a multiplier of 1000;
+ - [TP], [TOOL_NOTES] and [TDIA] in the tool-change comments.
+
+================================================

POST_NAME = "G-Code no arcs, Fanuc style (mm) (*.nc)"
FILE_EXTENSION = "nc"
UNITS = "MM"
LINE_ENDING = "[13][10]"

+ Parentheses end a Fanuc comment: print ( ) in names as [ ].
SUBSTITUTE = "([91])[93]"

LINE_NUMBER_START     = 10
LINE_NUMBER_INCREMENT = 10
LINE_NUMBER_MAXIMUM   = 990

SPINDLE_SPEED_RANGE = 1 15 4500 18000

VAR LINE_NUMBER = [N|A|N|1.0]
VAR SPINDLE_SPEED = [S|A|S|1.0]
VAR FEED_RATE = [F|A|F|#1.0]
VAR TOOL_NUMBER = [T|A||1.0]
VAR PREVIOUS_TOOL_NUMBER = [TP|A|T|1.0]
VAR TOOL_DIAMETER = [TDIA|A||1.2]
VAR X_POSITION = [X|C|X|1.3]
VAR Y_POSITION = [Y|C|Y|1.3]
VAR Z_POSITION = [Z|C|Z|1.3]
VAR X_HOME_POSITION = [XH|A|X|1.3]
VAR Y_HOME_POSITION = [YH|A|Y|1.3]
VAR Z_HOME_POSITION = [ZH|A|Z|1.3]
VAR DWELL_TIME = [DWELL|A|P|1.0|1000]

begin HEADER
"%"
"O0100 ([TP_FILENAME])"
"[N] G21 G90 G17 G40 G80"
"[N] (TOOL T[T] DIA [TDIA] [TOOLNAME] - [TOOL_NOTES])"
"[N] G91 G28 Z0"
"[N] G90 T[T] M6"
"[N] G43 H[T]"
"[N] G0[ZH]"

begin SPINDLE_ON
"[N] [S] M3"

begin TOOLCHANGE
"[N] M5"
"[N] (TOOL T[T] DIA [TDIA] [TOOLNAME] - [TOOL_NOTES] AFTER [TP])"
"[N] G91 G28 Z0"
"[N] G90 T[T] M6"
"[N] G43 H[T]"
"[N] G0[ZH]"

begin NEW_SEGMENT
"[N] ([TOOLPATH_NAME])"

begin RAPID_MOVE
"[N] G0[X][Y][Z]"

begin FEED_RATE_CHANGE
"[N] [F]"

begin FEED_MOVE
"[N] G1[X][Y][Z]"

begin DWELL_MOVE
"[N] G4 [DWELL]"

begin FOOTER
"[N] M5"
"[N] G91 G28 Z0"
"[N] G90 G0[XH][YH]"
"[N] M30"
"%"

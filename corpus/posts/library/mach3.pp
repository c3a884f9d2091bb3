+================================================
+
+ postc library: Mach3 / Mach4 3-axis mill or router, millimetres.
+
+ Written for postc from the Mach3/Mach4 G-code conventions: block numbers
+ N10, N20, ...; a preamble that cancels what a previous job may have left
+ (G40 cutter compensation, G49 length offset, G80 canned cycle) and sets
+ G91.1, incremental I J, because Mach can be configured either way;
+ T/M6 tool changes with G43 length offsets; helical G2/G3; G4 P dwells
+ (seconds: Mach3's default; a Mach3 set to milliseconds needs P x 1000);
+ retracts to machine Z zero (G53 G0 Z0); M30 at the end.
+
+================================================

POST_NAME = "Mach3/Mach4 (mm) (*.tap)"
FILE_EXTENSION = "tap"
UNITS = "MM"
LINE_ENDING = "[13][10]"

+ Parentheses end a G-code comment: print ( ) in names as { }.
SUBSTITUTE = "({)}"

LINE_NUMBER_START     = 10
LINE_NUMBER_INCREMENT = 10
LINE_NUMBER_MAXIMUM   = 9999990

VAR LINE_NUMBER = [N|A|N|1.0]
VAR SPINDLE_SPEED = [S|A|S|1.0]
VAR TOOL_NUMBER = [T|A||1.0]
VAR FEED_RATE = [F|C| F|1.1]
VAR X_POSITION = [X|C| X|1.4]
VAR Y_POSITION = [Y|C| Y|1.4]
VAR Z_POSITION = [Z|C| Z|1.4]
VAR ARC_CENTRE_I_INC_POSITION = [I|A| I|1.4]
VAR ARC_CENTRE_J_INC_POSITION = [J|A| J|1.4]
VAR DWELL_TIME = [DWELL|A|P|1.2]

begin HEADER
"[N] ( [TP_FILENAME] )"
"[N] ( toolpath: [TOOLPATH_NAME] )"
"[N] G21 G90 G17 G40 G49 G80 G94"
"[N] G91.1"
"[N] G53 G0 Z0"
"[N] ( tool [T]: [TOOLNAME] )"
"[N] T[T] M6"
"[N] G43 H[T]"

begin SPINDLE_ON
"[N] [S] M3"

begin TOOLCHANGE
"[N] M5"
"[N] G53 G0 Z0"
"[N] ( tool [T]: [TOOLNAME] )"
"[N] T[T] M6"
"[N] G43 H[T]"

begin NEW_SEGMENT
"[N] ( toolpath: [TOOLPATH_NAME] )"

begin RAPID_MOVE
"[N] G0[X][Y][Z]"

begin FIRST_FEED_MOVE
"[N] G1[X][Y][Z][F]"

begin FEED_MOVE
"[N] G1[X][Y][Z]"

begin FIRST_CW_ARC_MOVE
"[N] G2[X][Y][Z][I][J][F]"

begin CW_ARC_MOVE
"[N] G2[X][Y][Z][I][J]"

begin FIRST_CCW_ARC_MOVE
"[N] G3[X][Y][Z][I][J][F]"

begin CCW_ARC_MOVE
"[N] G3[X][Y][Z][I][J]"

begin DWELL_MOVE
"[N] G4 [DWELL]"

begin FOOTER
"[N] M5"
"[N] G53 G0 Z0"
"[N] M30"

+================================================
+
+ postc library: LinuxCNC (EMC2) 3-axis mill, millimetres.
+
+ Written for postc from LinuxCNC's G-code reference: G21 G90 G17 and G64
+ P0.01 (path blending within 0.01 mm) in the preamble, T/M6 tool changes
+ with G43 length offsets, helical G2/G3 with incremental I J, G4 P dwells
+ in seconds, safe retracts to machine Z zero (G53 G0 Z0), M2 at the end.
+ The program is wrapped in % lines, as LinuxCNC allows.
+
+================================================

POST_NAME = "LinuxCNC (mm) (*.ngc)"
FILE_EXTENSION = "ngc"
UNITS = "MM"
LINE_ENDING = "[10]"

+ Parentheses end a G-code comment: print ( ) in names as { }.
SUBSTITUTE = "({)}"

VAR SPINDLE_SPEED = [S|A|S|1.0]
VAR TOOL_NUMBER = [T|A||1.0]
VAR FEED_RATE = [F|C| F|1.1]
VAR X_POSITION = [X|C| X|1.4]
VAR Y_POSITION = [Y|C| Y|1.4]
VAR Z_POSITION = [Z|C| Z|1.4]
VAR ARC_CENTRE_I_INC_POSITION = [I|A| I|1.4]
VAR ARC_CENTRE_J_INC_POSITION = [J|A| J|1.4]
VAR DWELL_TIME = [DWELL|A|P|1.2]
VAR X_LENGTH = [XLENGTH|A||1.1]
VAR Y_LENGTH = [YLENGTH|A||1.1]
VAR Z_LENGTH = [ZLENGTH|A||1.1]

begin HEADER
"%"
"( [TP_FILENAME] )"
"( made by [PRODUCT] on [DATE] [TIME] )"
"( material [XLENGTH] x [YLENGTH] x [ZLENGTH] mm )"
"( toolpath: [TOOLPATH_NAME] )"
"G21 G90 G17 G40 G49 G54 G94"
"G64 P0.01"
"G53 G0 Z0"
"( tool [T]: [TOOLNAME] )"
"T[T] M6"
"G43 H[T]"

begin SPINDLE_ON
"[S] M3"

begin TOOLCHANGE
"M5"
"G53 G0 Z0"
"( tool [T]: [TOOLNAME] )"
"T[T] M6"
"G43 H[T]"

begin NEW_SEGMENT
"( toolpath: [TOOLPATH_NAME] )"

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

begin DWELL_MOVE
"G4 [DWELL]"

begin FOOTER
"M5"
"G53 G0 Z0"
"M2"
"%"

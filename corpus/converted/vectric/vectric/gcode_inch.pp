+ Converted by postc from gcode_inch.pp (Vectric)
+================================================
+
+ postc generic G-code post, inches.
+ The post `postc post TOOLPATH` uses when no post is named (it is
+ embedded in the binary). Output reads in LinuxCNC, Mach3/4, grbl and
+ most Fanuc-style controls: G20, absolute, XY plane, I/J relative arcs
+ with helical Z, G4 dwells, T/M6 tool changes with G43 length offsets.
+ Safe retracts go to machine Z zero (G53 G0 Z0), which is safe whether or
+ not the toolpath says where home is (APT CL files often do not).
+
+================================================

POST_NAME = "postc G-code (inch) (*.ngc)"
FILE_EXTENSION = "ngc"
UNITS = "INCH"
LINE_ENDING = "[10]"
LASER_SUPPORT = "YES"

+ Parentheses end a G-code comment: print ( ) in names as { }.
SUBSTITUTE = "({)}"

LINE_NUMBER_START     = 10
LINE_NUMBER_INCREMENT = 10
LINE_NUMBER_MAXIMUM   = 99999

VAR LINE_NUMBER = [N|A|N|1.0]
VAR SPINDLE_SPEED = [S|A|S|1.0]
VAR POWER = [P|A|S|1.0]
VAR TOOL_NUMBER = [T|A||1.0]
VAR FEED_RATE = [F|C|F|1.1]
VAR X_POSITION = [X|C|X|1.4]
VAR Y_POSITION = [Y|C|Y|1.4]
VAR Z_POSITION = [Z|C|Z|1.4]
VAR ARC_CENTRE_I_INC_POSITION = [I|A|I|1.5]
VAR ARC_CENTRE_J_INC_POSITION = [J|A|J|1.5]
VAR SAFE_Z_HEIGHT = [SAFEZ|A|Z|1.4]
VAR DWELL_TIME = [DWELL|A|P|1.2]
VAR X_LENGTH = [XLENGTH|A||1.1]
VAR Y_LENGTH = [YLENGTH|A||1.1]
VAR Z_LENGTH = [ZLENGTH|A||1.1]

begin HEADER
"( [TP_FILENAME] )"
"( made by [PRODUCT] on [DATE] [TIME] )"
"( material [XLENGTH] x [YLENGTH] x [ZLENGTH] in )"
"( tools: [TOOLS_USED] )"
"( toolpath: [TOOLPATH_NAME] )"
"G20 G90 G17 G40 G49 G94"
"G53 G0 Z0"
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
"G4[DWELL]"

begin JET_TOOL_ON
"M3[P]"

begin JET_TOOL_POWER
"[P]"

begin JET_TOOL_OFF
"M5"

begin FOOTER
"M5"
"G53 G0 Z0"
"M30"

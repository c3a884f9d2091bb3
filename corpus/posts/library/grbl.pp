+================================================
+
+ postc library: grbl 1.1 router or laser, millimetres.
+
+ Written for postc from grbl 1.1's list of supported G-code: no block
+ numbers, no tool length offsets and no M6 (grbl refuses M6): a tool change
+ stops the spindle, raises Z to the safe height and pauses with M0 for the
+ operator to change the tool and set its height, then resumes. Arcs are
+ G2/G3 with incremental I J and helical Z; dwells are G4 P in seconds.
+ Jet (laser) toolpaths use grbl's laser mode: M4 with the power as S.
+ Retracts go to the toolpath's safe Z (grbl machines usually home to the
+ top of Z, but work zero is what the operator set).
+
+================================================

POST_NAME = "grbl (mm) (*.nc)"
FILE_EXTENSION = "nc"
UNITS = "MM"
LINE_ENDING = "[10]"
LASER_SUPPORT = "YES"

+ Parentheses end a G-code comment: print ( ) in names as { }.
SUBSTITUTE = "({)}"

VAR SPINDLE_SPEED = [S|A|S|1.0]
VAR POWER = [P|A|S|1.0]
VAR TOOL_NUMBER = [T|A||1.0]
VAR FEED_RATE = [F|C|F|1.0]
VAR X_POSITION = [X|C|X|1.3]
VAR Y_POSITION = [Y|C|Y|1.3]
VAR Z_POSITION = [Z|C|Z|1.3]
VAR ARC_CENTRE_I_INC_POSITION = [I|A|I|1.3]
VAR ARC_CENTRE_J_INC_POSITION = [J|A|J|1.3]
VAR SAFE_Z_HEIGHT = [SAFEZ|A|Z|1.3]
VAR X_HOME_POSITION = [XH|A|X|1.3]
VAR Y_HOME_POSITION = [YH|A|Y|1.3]
VAR DWELL_TIME = [DWELL|A|P|1.2]

begin HEADER
"( [TP_FILENAME] )"
"( tool [T]: [TOOLNAME] )"
"G21 G90 G17 G94"
"G0[SAFEZ]"

begin SPINDLE_ON
"[S] M3"

begin TOOLCHANGE
"M5"
"G0[SAFEZ]"
"( change to tool [T]: [TOOLNAME] )"
"M0"

begin NEW_SEGMENT
"( [TOOLPATH_NAME] )"

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
"M4 [P]"

begin JET_TOOL_POWER
"[P]"

begin JET_TOOL_OFF
"M5"

begin FOOTER
"M5"
"G0[SAFEZ]"
"G0[XH][YH]"
"M30"

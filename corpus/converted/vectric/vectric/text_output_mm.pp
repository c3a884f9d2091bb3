+ Converted by postc from text_output_mm.pp (Vectric)
+================================================
+
+ postc corpus: a readable listing of every section (mm), in the manner
+ of Vectric's TextOutput_Arcs_mm.pp.
+
+ Every section of both Vectric guides is here and names itself, so the
+ goldens of this post show which section the runtime chose for each
+ event (FIRST_ or plain, plunge, retract, helical, helical plunge, jet,
+ dwell, feed-rate change, ...). It prints every variable of both
+ guides' tables: the arc words [I] [J] [IA] [JA] [ArcStartX]
+ [ArcStartY] [ArcMidX] [ArcMidY] [ArcMidXI] [ArcMidYI] [Radius] and
+ [Angle] (in degrees through a multiplier), job and file data, [FI],
+ [P], [DWELL], [TDIA], [PRODUCT].
+
+ Block numbers are zero padded to four digits (0 flag, width 4),
+ start at 1 and wrap after 9999.
+
+================================================

POST_NAME = "Text listing (mm) (*.txt)"
FILE_EXTENSION = "txt"
UNITS = "MM"
LINE_ENDING = "[10]"
PRINT_DIRECT = "NO"
DIRECT_OUTPUT = "Listing|Notepad.Document"
LASER_SUPPORT = "YES"

LINE_NUMBER_START     = 1
LINE_NUMBER_INCREMENT = 1
LINE_NUMBER_MAXIMUM   = 9999

VAR LINE_NUMBER = [N|A||04.0]
VAR SPINDLE_SPEED = [S|A||1.0]
VAR POWER = [P|A||1.1]
VAR FEED_RATE = [F|A||1.1]
VAR CUT_RATE = [FC|A||1.1]
VAR PLUNGE_RATE = [FP|A||1.1]
VAR INVERSE_TIME = [FI|A||1.4]
VAR TOOL_NUMBER = [T|A||1.0]
VAR PREVIOUS_TOOL_NUMBER = [TP|A||1.0]
VAR TOOL_DIAMETER = [TDIA|A||1.3]
VAR X_POSITION = [X|A||1.3]
VAR Y_POSITION = [Y|A||1.3]
VAR Z_POSITION = [Z|A||1.3]
VAR A_POSITION = [A|A||1.3]
VAR ARC_CENTRE_I_INC_POSITION = [I|A||1.3]
VAR ARC_CENTRE_J_INC_POSITION = [J|A||1.3]
VAR ARC_CENTRE_I_ABS_POSITION = [IA|A||1.3]
VAR ARC_CENTRE_J_ABS_POSITION = [JA|A||1.3]
VAR ARC_START_X_POSITION = [ArcStartX|A||1.3]
VAR ARC_START_Y_POSITION = [ArcStartY|A||1.3]
VAR ARC_MID_X_POSITION = [ArcMidX|A||1.3]
VAR ARC_MID_Y_POSITION = [ArcMidY|A||1.3]
VAR ARC_MID_X_INC_POSITION = [ArcMidXI|A||1.3]
VAR ARC_MID_Y_INC_POSITION = [ArcMidYI|A||1.3]
VAR ARC_RADIUS = [Radius|A||1.3]
VAR ARC_ANGLE = [Angle|A||1.3|57.2957795]
VAR X_HOME_POSITION = [XH|A||1.3]
VAR Y_HOME_POSITION = [YH|A||1.3]
VAR Z_HOME_POSITION = [ZH|A||1.3]
VAR SAFE_Z_HEIGHT = [SAFEZ|A||1.3]
VAR WRAP_DIAMETER = [WRAP_DIA|A||1.3]
VAR X_LENGTH = [XLENGTH|A||1.3]
VAR Y_LENGTH = [YLENGTH|A||1.3]
VAR Z_LENGTH = [ZLENGTH|A||1.3]
VAR X_MIN = [XMIN|A||1.3]
VAR Y_MIN = [YMIN|A||1.3]
VAR Z_MIN = [ZMIN|A||1.3]
VAR X_MAX = [XMAX|A||1.3]
VAR Y_MAX = [YMAX|A||1.3]
VAR Z_MAX = [ZMAX|A||1.3]
VAR X_ORIGIN_POS = [X_ORIGIN_POS|A||1.3]
VAR Y_ORIGIN_POS = [Y_ORIGIN_POS|A||1.3]
VAR DWELL_TIME = [DWELL|A||1.2]

begin HEADER
"[N] HEADER"
"[N]   file [TP_FILENAME] ext [TP_EXT] dir [TP_DIR] path [PATHNAME]"
"[N]   made by [PRODUCT] on [DATE] at [TIME]"
"[N]   notes [FILE_NOTES]"
"[N]   tools used [TOOLS_USED]"
"[N]   toolpaths [TOOLPATHS_OUTPUT]"
"[N]   block [XLENGTH] x [YLENGTH] x [ZLENGTH], from [XMIN],[YMIN],[ZMIN] to [XMAX],[YMAX],[ZMAX]"
"[N]   origin [XY_ORIGIN] at [X_ORIGIN_POS],[Y_ORIGIN_POS], Z zero on [Z_ORIGIN]"
"[N]   home [XH],[YH],[ZH] safe Z [SAFEZ] wrap diameter [WRAP_DIA]"
"[N]   tool [T] after [TP]: [TOOLNAME] ([TOOL_NOTES]) dia [TDIA] speed [S] cut [FC] plunge [FP] power [P]"
"[N]   toolpath [TOOLPATH_NAME] ([TOOLPATH_NOTES])"

begin SPINDLE_ON
"[N] SPINDLE_ON speed [S]"

begin TOOLCHANGE
"[N] TOOLCHANGE tool [T] after [TP]: [TOOLNAME] ([TOOL_NOTES]) dia [TDIA] speed [S] cut [FC] plunge [FP]"

begin NEW_SEGMENT
"[N] NEW_SEGMENT [TOOLPATH_NAME] ([TOOLPATH_NOTES]) tool [T]"

begin INITIAL_RAPID_MOVE
"[N] INITIAL_RAPID_MOVE [X],[Y],[Z] A [A]"

begin RAPID_MOVE
"[N] RAPID_MOVE [X],[Y],[Z] A [A]"

begin FEED_RATE_CHANGE
"[N] FEED_RATE_CHANGE [F]"

begin FIRST_FEED_MOVE
"[N] FIRST_FEED_MOVE [X],[Y],[Z] F [F] FI [FI]"

begin FEED_MOVE
"[N] FEED_MOVE [X],[Y],[Z] F [F] FI [FI]"

begin FIRST_PLUNGE_MOVE
"[N] FIRST_PLUNGE_MOVE [X],[Y],[Z] F [F]"

begin PLUNGE_MOVE
"[N] PLUNGE_MOVE [X],[Y],[Z] F [F]"

begin RETRACT_MOVE
"[N] RETRACT_MOVE [X],[Y],[Z] F [F]"

begin FIRST_CW_ARC_MOVE
"[N] FIRST_CW_ARC_MOVE [X],[Y],[Z] F [F] FI [FI]"
"[N]   from [ArcStartX],[ArcStartY] via [ArcMidX],[ArcMidY] (rel [ArcMidXI],[ArcMidYI]) centre [IA],[JA] (rel [I],[J]) r [Radius] angle [Angle]"

begin CW_ARC_MOVE
"[N] CW_ARC_MOVE [X],[Y],[Z] F [F] FI [FI]"
"[N]   from [ArcStartX],[ArcStartY] via [ArcMidX],[ArcMidY] (rel [ArcMidXI],[ArcMidYI]) centre [IA],[JA] (rel [I],[J]) r [Radius] angle [Angle]"

begin FIRST_CCW_ARC_MOVE
"[N] FIRST_CCW_ARC_MOVE [X],[Y],[Z] F [F] FI [FI]"
"[N]   from [ArcStartX],[ArcStartY] via [ArcMidX],[ArcMidY] (rel [ArcMidXI],[ArcMidYI]) centre [IA],[JA] (rel [I],[J]) r [Radius] angle [Angle]"

begin CCW_ARC_MOVE
"[N] CCW_ARC_MOVE [X],[Y],[Z] F [F] FI [FI]"
"[N]   from [ArcStartX],[ArcStartY] via [ArcMidX],[ArcMidY] (rel [ArcMidXI],[ArcMidYI]) centre [IA],[JA] (rel [I],[J]) r [Radius] angle [Angle]"

begin FIRST_CW_HELICAL_ARC_MOVE
"[N] FIRST_CW_HELICAL_ARC_MOVE [X],[Y],[Z] F [F] centre [IA],[JA] r [Radius] angle [Angle]"

begin CW_HELICAL_ARC_MOVE
"[N] CW_HELICAL_ARC_MOVE [X],[Y],[Z] F [F] centre [IA],[JA] r [Radius] angle [Angle]"

begin FIRST_CCW_HELICAL_ARC_MOVE
"[N] FIRST_CCW_HELICAL_ARC_MOVE [X],[Y],[Z] F [F] centre [IA],[JA] r [Radius] angle [Angle]"

begin CCW_HELICAL_ARC_MOVE
"[N] CCW_HELICAL_ARC_MOVE [X],[Y],[Z] F [F] centre [IA],[JA] r [Radius] angle [Angle]"

begin FIRST_CW_HELICAL_ARC_PLUNGE_MOVE
"[N] FIRST_CW_HELICAL_ARC_PLUNGE_MOVE [X],[Y],[Z] F [F] centre [IA],[JA] r [Radius] angle [Angle]"

begin CW_HELICAL_ARC_PLUNGE_MOVE
"[N] CW_HELICAL_ARC_PLUNGE_MOVE [X],[Y],[Z] F [F] centre [IA],[JA] r [Radius] angle [Angle]"

begin FIRST_CCW_HELICAL_ARC_PLUNGE_MOVE
"[N] FIRST_CCW_HELICAL_ARC_PLUNGE_MOVE [X],[Y],[Z] F [F] centre [IA],[JA] r [Radius] angle [Angle]"

begin CCW_HELICAL_ARC_PLUNGE_MOVE
"[N] CCW_HELICAL_ARC_PLUNGE_MOVE [X],[Y],[Z] F [F] centre [IA],[JA] r [Radius] angle [Angle]"

begin DWELL_MOVE
"[N] DWELL_MOVE [DWELL] s"

begin JET_TOOL_POWER
"[N] JET_TOOL_POWER [P]"

begin JET_TOOL_ON
"[N] JET_TOOL_ON power [P]"

begin JET_TOOL_OFF
"[N] JET_TOOL_OFF"

begin FOOTER
"[N] FOOTER home [XH],[YH],[ZH]"

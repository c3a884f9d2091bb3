+ Converted by postc from shopbot_inch.pp (Vectric)
+================================================
+
+ postc corpus: ShopBot OpenSBP with tool changes (inch).
+
+ Demonstrates:
+ - OpenSBP commands: J2/J3/JZ jogs, M3 moves, CG arcs (1 clockwise,
+   -1 counter-clockwise, centre relative to the start), MS speeds,
+   TR spindle rpm, PAUSE for dwells, C6/C7/C9 custom cuts;
+ - speeds in inches per second: [F] [FC] [FP] through a multiplier of
+   1/60;
+ - INITIAL_RAPID_MOVE: the first rapid after the header or a tool
+   change jogs XY first, then Z;
+ - FEED_RATE_CHANGE setting MS when the feed changes (M3 carries no
+   speed);
+ - arc sections without [Z]: helices are linearized;
+ - the defaults of undeclared labels: [XMIN] [XMAX] [YMIN] [YMAX]
+   [ZMIN] [ZMAX] print with no prefix and 3 decimals, so the line
+   writes its own blanks, as VCarve's ShopBot posts do
+   ("'Length of material in X = [XLENGTH]");
+ - job data: [Z_ORIGIN] [XY_ORIGIN] [X_ORIGIN_POS] [Y_ORIGIN_POS]
+   [SAFEZ] [ZLENGTH] [FILE_NOTES] [TOOLPATHS_OUTPUT] [DATE] [TIME]
+   [PRODUCT];
+ - SUBSTITUTE with a [nn] code: commas in names print as ;.
+
+================================================

POST_NAME = "ShopBot TC (inch) (*.sbp)"
FILE_EXTENSION = "sbp"
UNITS = "INCHES"
LINE_ENDING = "[13][10]"
RAPID_PLUNGE_TO_STARTZ = "NO"

+ Commas separate OpenSBP arguments.
SUBSTITUTE = "[44];"

VAR SPINDLE_SPEED = [S|A||1.0]
VAR FEED_RATE = [F|A||1.3|0.0166667]
VAR CUT_RATE = [FC|A||1.3|0.0166667]
VAR PLUNGE_RATE = [FP|A||1.3|0.0166667]
VAR X_POSITION = [X|A||1.4]
VAR Y_POSITION = [Y|A||1.4]
VAR Z_POSITION = [Z|A||1.4]
VAR ARC_CENTRE_I_INC_POSITION = [I|A||1.4]
VAR ARC_CENTRE_J_INC_POSITION = [J|A||1.4]
VAR X_HOME_POSITION = [XH|A||1.4]
VAR Y_HOME_POSITION = [YH|A||1.4]
VAR Z_HOME_POSITION = [ZH|A||1.4]
VAR SAFE_Z_HEIGHT = [SAFEZ|A||1.4]
VAR Z_LENGTH = [ZLENGTH|A||1.4]
VAR X_ORIGIN_POS = [X_ORIGIN_POS|A||1.4]
VAR Y_ORIGIN_POS = [Y_ORIGIN_POS|A||1.4]
VAR DWELL_TIME = [DWELL|A||1.2]

begin HEADER
"'[TP_FILENAME]"
"'Made by [PRODUCT] on [DATE] at [TIME]"
"'Material X [XMIN] to [XMAX], Y [YMIN] to [YMAX], Z [ZMIN] to [ZMAX]"
"'Origin [XY_ORIGIN] at [X_ORIGIN_POS], [Y_ORIGIN_POS]"
"'Notes: [FILE_NOTES]"
"'Toolpaths: [TOOLPATHS_OUTPUT]"
"&PWZorigin = [Z_ORIGIN]"
"&PWSafeZ = [SAFEZ]"
"&PWMaterial = [ZLENGTH]"
"SA"
"'Tool [T]: [TOOLNAME]"
"&Tool = [T]"
"C9"
"MS,[FC],[FP]"
"JZ,[ZH]"
"J2,[XH],[YH]"

begin SPINDLE_ON
"TR,[S]"
"C6"
"PAUSE 2"

begin TOOLCHANGE
"C7"
"'Tool [T]: [TOOLNAME] replaces tool [TP]"
"&Tool = [T]"
"C9"

begin NEW_SEGMENT
"'Toolpath: [TOOLPATH_NAME]"
"MS,[FC],[FP]"

begin INITIAL_RAPID_MOVE
"J2,[X],[Y]"
"JZ,[Z]"

begin RAPID_MOVE
"J3,[X],[Y],[Z]"

begin FEED_RATE_CHANGE
"MS,[F],[FP]"

begin FEED_MOVE
"M3,[X],[Y],[Z]"

begin CW_ARC_MOVE
"CG,,[X],[Y],[I],[J],T,1"

begin CCW_ARC_MOVE
"CG,,[X],[Y],[I],[J],T,-1"

begin DWELL_MOVE
"PAUSE [DWELL]"

begin FOOTER
"C7"
"JZ,[ZH]"
"J2,[XH],[YH]"
"END"

+ Converted by postc from tape_split_mm.pp (Vectric)
+================================================
+
+ postc corpus: G-code ATC with arcs and helices, tape splitting (mm).
+
+ Demonstrates:
+ - TAPE_SPLITTING = 40 15 "%s_%d.nc" 1 "YES": parts of at most 40
+   blocks (plus the footer), split after a retract to safe Z once a
+   part has 25, every part named name_1.nc, name_2.nc, ...
+   (INDEX_ON_FIRST_FILE); each part starts with HEADER and SPINDLE_ON
+   and ends with FOOTER; a program that fits is not split;
+ - all eight helical sections: FIRST_ and plain CW/CCW
+   HELICAL_ARC_MOVE and HELICAL_ARC_PLUNGE_MOVE (the plunge ones at the
+   plunge feed, marked with a comment);
+ - FIRST_PLUNGE_MOVE / PLUNGE_MOVE and FIRST_FEED_MOVE / FEED_MOVE;
+ - [TOOLPATH_NOTES], [TP_DIR], [TP_EXT], [PATHNAME], [FC], [FP].
+
+================================================

POST_NAME = "G-Code ATC Arcs TS40 (mm) (*.nc)"
FILE_EXTENSION = "nc"
UNITS = "MM"
LINE_ENDING = "[10]"
SUBSTITUTE = "({)}"

TAPE_SPLITTING = 40 15 "%s_%d.nc" 1 "YES"

VAR SPINDLE_SPEED = [S|A|S|1.0]
VAR FEED_RATE = [F|C|F|1.1]
VAR CUT_RATE = [FC|A||1.0]
VAR PLUNGE_RATE = [FP|A||1.0]
VAR X_POSITION = [X|C|X|1.3]
VAR Y_POSITION = [Y|C|Y|1.3]
VAR Z_POSITION = [Z|C|Z|1.3]
VAR ARC_CENTRE_I_INC_POSITION = [I|A|I|1.3]
VAR ARC_CENTRE_J_INC_POSITION = [J|A|J|1.3]
VAR X_HOME_POSITION = [XH|A|X|1.3]
VAR Y_HOME_POSITION = [YH|A|Y|1.3]
VAR Z_HOME_POSITION = [ZH|A|Z|1.3]
VAR DWELL_TIME = [DWELL|A|P|1.2]

begin HEADER
"( [TP_FILENAME].[TP_EXT] in [TP_DIR] )"
"( path [PATHNAME] )"
"G21 G90 G17 G40 G49 G94"
"G0[ZH]"
"T[T] M6"
"G43 H[T]"
"( [TOOLPATH_NAME]: [TOOLPATH_NOTES] )"
"( cut [FC] plunge [FP] mm/min )"

begin SPINDLE_ON
"[S] M3"

begin TOOLCHANGE
"M5"
"G0[ZH]"
"T[T] M6"
"G43 H[T]"

begin NEW_SEGMENT
"( [TOOLPATH_NAME]: [TOOLPATH_NOTES] )"
"( cut [FC] plunge [FP] mm/min )"

begin RAPID_MOVE
"G0[X][Y][Z]"

begin FIRST_PLUNGE_MOVE
"G1[X][Y][Z][F]"

begin PLUNGE_MOVE
"G1[X][Y][Z]"

begin FIRST_FEED_MOVE
"G1[X][Y][Z][F]"

begin FEED_MOVE
"G1[X][Y][Z]"

begin FIRST_CW_ARC_MOVE
"G2[X][Y][I][J][F]"

begin CW_ARC_MOVE
"G2[X][Y][I][J]"

begin FIRST_CCW_ARC_MOVE
"G3[X][Y][I][J][F]"

begin CCW_ARC_MOVE
"G3[X][Y][I][J]"

begin FIRST_CW_HELICAL_ARC_MOVE
"G2[X][Y][Z][I][J][F]"

begin CW_HELICAL_ARC_MOVE
"G2[X][Y][Z][I][J]"

begin FIRST_CCW_HELICAL_ARC_MOVE
"G3[X][Y][Z][I][J][F]"

begin CCW_HELICAL_ARC_MOVE
"G3[X][Y][Z][I][J]"

begin FIRST_CW_HELICAL_ARC_PLUNGE_MOVE
"G2[X][Y][Z][I][J][F] ( helical plunge )"

begin CW_HELICAL_ARC_PLUNGE_MOVE
"G2[X][Y][Z][I][J] ( helical plunge )"

begin FIRST_CCW_HELICAL_ARC_PLUNGE_MOVE
"G3[X][Y][Z][I][J][F] ( helical plunge )"

begin CCW_HELICAL_ARC_PLUNGE_MOVE
"G3[X][Y][Z][I][J] ( helical plunge )"

begin DWELL_MOVE
"G4[DWELL]"

begin FOOTER
"M5"
"G0[ZH]"
"G0[XH][YH]"
"M30"

+ Converted by postc from heidenhain_mm.pp (Vectric)
+================================================
+
+ postc corpus: Heidenhain conversational (plain language), mm.
+
+ Demonstrates:
+ - a comma decimal separator and a forced sign: X+10,000 Y-5,000;
+ - conversational blocks: L X+10,000 Y+5,000 Z+5,000 R0 FMAX, arcs as
+   CC (absolute centre, [IA] [JA]) then C ... DR- / DR+;
+ - the - flag (the tool diameter left justified in a width of 8) and
+   the 0 flag (the previous tool zero padded to three digits);
+ - block numbers from 0 in steps of 1 on every block;
+ - MIN_ARC_RADIUS (arcs under 0.5 mm print as one L block) and
+   MAX_ARC_RADIUS (arcs over 500 mm are linearized);
+ - arc sections without [Z], so helices are linearized;
+ - RETRACT_MOVE printing straight retracts at FMAX;
+ - DWELL_MOVE as cycle 9 with a comma decimal;
+ - F is modal, FMAX applies to its own block only.
+
+================================================

POST_NAME = "Heidenhain conversational (mm) (*.h)"
FILE_EXTENSION = "h"
UNITS = "MM"
LINE_ENDING = "[13][10]"

LINE_NUMBER_START     = 0
LINE_NUMBER_INCREMENT = 1
LINE_NUMBER_MAXIMUM   = 99999

MIN_ARC_RADIUS = 0.5
MAX_ARC_RADIUS = 500

VAR LINE_NUMBER = [N|A||1.0]
VAR SPINDLE_SPEED = [S|A| S|1.0]
VAR FEED_RATE = [F|C| F|1.0]
VAR TOOL_NUMBER = [T|A||1.0]
VAR PREVIOUS_TOOL_NUMBER = [TP|A|T|03.0]
VAR TOOL_DIAMETER = [TDIA|A||-8,3]
VAR X_POSITION = [X|A| X|+1,3]
VAR Y_POSITION = [Y|A| Y|+1,3]
VAR Z_POSITION = [Z|A| Z|+1,3]
VAR ARC_CENTRE_I_ABS_POSITION = [IA|A| X|+1,3]
VAR ARC_CENTRE_J_ABS_POSITION = [JA|A| Y|+1,3]
VAR X_HOME_POSITION = [XH|A| X|+1,3]
VAR Y_HOME_POSITION = [YH|A| Y|+1,3]
VAR Z_HOME_POSITION = [ZH|A| Z|+1,3]
VAR X_MIN = [XMIN|A| X|+1,3]
VAR Y_MIN = [YMIN|A| Y|+1,3]
VAR Z_MIN = [ZMIN|A| Z|+1,3]
VAR X_MAX = [XMAX|A| X|+1,3]
VAR Y_MAX = [YMAX|A| Y|+1,3]
VAR Z_MAX = [ZMAX|A| Z|+1,3]
VAR DWELL_TIME = [DWELL|A||1,2]

begin HEADER
"[N] BEGIN PGM [TP_FILENAME] MM"
"[N] ; [FILE_NOTES]"
"[N] BLK FORM 0.1 Z[XMIN][YMIN][ZMIN]"
"[N] BLK FORM 0.2[XMAX][YMAX][ZMAX]"
"[N] ; T[T] DIA [TDIA] [TOOLNAME]"
"[N] TOOL CALL [T] Z[S]"

begin SPINDLE_ON
"[N] L[ZH] R0 FMAX M3"

begin TOOLCHANGE
"[N] L[ZH] R0 FMAX M5"
"[N] ; T[T] DIA [TDIA] [TOOLNAME] REPLACES [TP]"
"[N] TOOL CALL [T] Z[S]"

begin NEW_SEGMENT
"[N] ; [TOOLPATH_NAME]"

begin RAPID_MOVE
"[N] L[X][Y][Z] R0 FMAX"

begin RETRACT_MOVE
"[N] L[Z] R0 FMAX"

begin FEED_MOVE
"[N] L[X][Y][Z][F]"

begin CW_ARC_MOVE
"[N] CC[IA][JA]"
"[N] C[X][Y] DR-[F]"

begin CCW_ARC_MOVE
"[N] CC[IA][JA]"
"[N] C[X][Y] DR+[F]"

begin DWELL_MOVE
"[N] CYCL DEF 9.0 DWELL TIME"
"[N] CYCL DEF 9.1 DWELL [DWELL]"

begin FOOTER
"[N] L[ZH] R0 FMAX M5"
"[N] L[XH][YH] R0 FMAX M30"
"[N] END PGM [TP_FILENAME] MM"

+================================================
+
+ postc library: Heidenhain TNC conversational (plain language), mm.
+
+ Written for postc from Heidenhain's conversational programming
+ conventions: BEGIN PGM / END PGM, a BLK FORM workpiece blank from the
+ job's material, TOOL CALL n Z S..., straight lines as L X+.. Y+.. Z+..
+ R0 with FMAX for rapids, arcs as CC (the absolute centre) then C with
+ DR- (clockwise) or DR+ (counter-clockwise), block numbers from 0 in
+ steps of 1, comments after a semicolon, dwells as cycle 9. Retracts go
+ to machine Z zero (L Z+0 R0 FMAX M91). Helices are cut into straight
+ lines (the arc sections print no Z).
+
+ postc verify does not read conversational programs: this post's output
+ is checked by its goldens (docs/posts.md).
+
+================================================

POST_NAME = "Heidenhain TNC conversational (mm) (*.h)"
FILE_EXTENSION = "h"
UNITS = "MM"
LINE_ENDING = "[13][10]"

LINE_NUMBER_START     = 0
LINE_NUMBER_INCREMENT = 1
LINE_NUMBER_MAXIMUM   = 99999

VAR LINE_NUMBER = [N|A||1.0]
VAR SPINDLE_SPEED = [S|A| S|1.0]
VAR FEED_RATE = [F|C| F|1.0]
VAR TOOL_NUMBER = [T|A||1.0]
VAR X_POSITION = [X|A| X|+1.3]
VAR Y_POSITION = [Y|A| Y|+1.3]
VAR Z_POSITION = [Z|A| Z|+1.3]
VAR ARC_CENTRE_I_ABS_POSITION = [IA|A| X|+1.3]
VAR ARC_CENTRE_J_ABS_POSITION = [JA|A| Y|+1.3]
VAR SAFE_Z_HEIGHT = [SAFEZ|A| Z|+1.3]
VAR X_HOME_POSITION = [XH|A| X|+1.3]
VAR Y_HOME_POSITION = [YH|A| Y|+1.3]
VAR X_MIN = [XMIN|A| X|+1.3]
VAR Y_MIN = [YMIN|A| Y|+1.3]
VAR Z_MIN = [ZMIN|A| Z|+1.3]
VAR X_MAX = [XMAX|A| X|+1.3]
VAR Y_MAX = [YMAX|A| Y|+1.3]
VAR Z_MAX = [ZMAX|A| Z|+1.3]
VAR DWELL_TIME = [DWELL|A||1.2]

begin HEADER
"[N] BEGIN PGM [TP_FILENAME] MM"
"[N] ; made by [PRODUCT] on [DATE] [TIME]"
"[N] BLK FORM 0.1 Z[XMIN][YMIN][ZMIN]"
"[N] BLK FORM 0.2[XMAX][YMAX][ZMAX]"
"[N] ; toolpath: [TOOLPATH_NAME]"
"[N] L Z+0 R0 FMAX M91"
"[N] ; tool [T]: [TOOLNAME]"
"[N] TOOL CALL [T] Z[S]"

begin SPINDLE_ON
"[N] L[SAFEZ] R0 FMAX M3"

begin TOOLCHANGE
"[N] L Z+0 R0 FMAX M91 M5"
"[N] ; tool [T]: [TOOLNAME]"
"[N] TOOL CALL [T] Z[S]"

begin NEW_SEGMENT
"[N] ; toolpath: [TOOLPATH_NAME]"

begin RAPID_MOVE
"[N] L[X][Y][Z] R0 FMAX"

begin FEED_MOVE
"[N] L[X][Y][Z] R0[F]"

begin CW_ARC_MOVE
"[N] CC[IA][JA]"
"[N] C[X][Y] DR- R0[F]"

begin CCW_ARC_MOVE
"[N] CC[IA][JA]"
"[N] C[X][Y] DR+ R0[F]"

begin DWELL_MOVE
"[N] CYCL DEF 9.0 DWELL TIME"
"[N] CYCL DEF 9.1 DWELL [DWELL]"

begin FOOTER
"[N] L Z+0 R0 FMAX M91 M5"
"[N] L[XH][YH] R0 FMAX M30"
"[N] END PGM [TP_FILENAME] MM"

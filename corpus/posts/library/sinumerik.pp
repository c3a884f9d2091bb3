+================================================
+
+ postc library: Siemens Sinumerik 840D / 828D 3-axis mill, millimetres.
+
+ Written for postc from Sinumerik's programming conventions: comments after
+ a semicolon, block numbers N10, N20, ...; G71 (metric) with G17 G40 G90
+ G94; tools as T with cutting edge D1 and M6; G2/G3 with incremental I J
+ (helical when Z changes); G4 F dwells in seconds; retracts to machine Z
+ zero with SUPA (every frame off for that block); M30 at the end.
+ Drilling prints as moves (Vectric posts have no cycle sections), so no
+ CYCLE81/CYCLE83 call depends on the machine's cycle set-up.
+
+================================================

POST_NAME = "Sinumerik 840D (mm) (*.mpf)"
FILE_EXTENSION = "mpf"
UNITS = "MM"
LINE_ENDING = "[10]"

LINE_NUMBER_START     = 10
LINE_NUMBER_INCREMENT = 10
LINE_NUMBER_MAXIMUM   = 9999990

VAR LINE_NUMBER = [N|A|N|1.0]
VAR SPINDLE_SPEED = [S|A|S|1.0]
VAR TOOL_NUMBER = [T|A||1.0]
VAR FEED_RATE = [F|C| F|1.1]
VAR X_POSITION = [X|C| X|1.3]
VAR Y_POSITION = [Y|C| Y|1.3]
VAR Z_POSITION = [Z|C| Z|1.3]
VAR ARC_CENTRE_I_INC_POSITION = [I|A| I|1.3]
VAR ARC_CENTRE_J_INC_POSITION = [J|A| J|1.3]
VAR DWELL_TIME = [DWELL|A|F|1.2]

begin HEADER
"; [TP_FILENAME]"
"; made by [PRODUCT] on [DATE] [TIME]"
"; toolpath: [TOOLPATH_NAME]"
"[N] G17 G40 G71 G90 G94"
"[N] G0 SUPA Z0"
"; tool [T]: [TOOLNAME]"
"[N] T[T] D1"
"[N] M6"

begin SPINDLE_ON
"[N] [S] M3"

begin TOOLCHANGE
"[N] M5"
"[N] G0 SUPA Z0"
"; tool [T]: [TOOLNAME]"
"[N] T[T] D1"
"[N] M6"

begin NEW_SEGMENT
"; toolpath: [TOOLPATH_NAME]"

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
"[N] G0 SUPA Z0"
"[N] M30"

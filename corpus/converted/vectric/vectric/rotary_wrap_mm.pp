+ Converted by postc from rotary_wrap_mm.pp (Vectric)
+================================================
+
+ postc corpus: G-code with Y wrapped onto a rotary A axis, inverse-time
+ feeds (mm).
+
+ Demonstrates:
+ - ROTARY_WRAP_Y = "-A": Y values print as degrees of A around a
+   cylinder of the job's wrap diameter ([WRAP_DIA]), turning the other
+   way ("-"); the Y prefix of [Y] becomes A;
+ - INVERSE_TIME_MODE with G93 and [FI]: every feed block carries
+   F = 1 / minutes for that move;
+ - no arc sections (rotary machines rarely take arcs around A): arcs
+   are linearized in the unrolled plane, then wrapped;
+ - [A] (the wrapped angle) in a comment.
+
+================================================

POST_NAME = "G-Code WrapY2A G93 (mm) (*.ngc)"
FILE_EXTENSION = "ngc"
UNITS = "MM"
LINE_ENDING = "[10]"

+ Names print in ( ) comments: parentheses in them print as braces.
SUBSTITUTE = "({)}"

ROTARY_WRAP_Y = "-A"
INVERSE_TIME_MODE = "YES"

VAR SPINDLE_SPEED = [S|A|S|1.0]
VAR INVERSE_TIME = [FI|A|F|1.3]
VAR X_POSITION = [X|C|X|1.3]
VAR Y_POSITION = [Y|C|Y|1.3]
VAR Z_POSITION = [Z|C|Z|1.3]
VAR A_POSITION = [A|A|A|1.3]
VAR X_HOME_POSITION = [XH|A|X|1.3]
VAR Z_HOME_POSITION = [ZH|A|Z|1.3]
VAR WRAP_DIAMETER = [WRAP_DIA|A||1.3]
VAR X_LENGTH = [XLENGTH|A||1.1]

begin HEADER
"( [TP_FILENAME] )"
"( stock length [XLENGTH] mm, diameter [WRAP_DIA] mm )"
"( Y values wrapped around X, output as -A degrees )"
"G21 G90 G17 G40 G49"
"G93"
"G0[ZH]"
"T[T] M6"

begin SPINDLE_ON
"[S] M3"

begin TOOLCHANGE
"M5"
"G0[ZH]"
"T[T] M6"

begin NEW_SEGMENT
"( [TOOLPATH_NAME] )"

begin RAPID_MOVE
"G0[X][Y][Z]"

begin FEED_MOVE
"G1[X][Y][Z][FI]"

begin FOOTER
"M5"
"G0[ZH]"
"( last rotary position [A] )"
"G0[XH] A0"
"G94"
"M30"

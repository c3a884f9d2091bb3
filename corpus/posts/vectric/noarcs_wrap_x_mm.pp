+================================================
+
+ postc corpus: gcode_noarcs_mm.pp with X wrapped onto a rotary B axis.
+
+ Demonstrates:
+ - POST_BASE: every statement, VAR and section of gcode_noarcs_mm.pp
+   (read from this folder), with the statements, VARs and sections
+   below overriding them one by one;
+ - ROTARY_WRAP_X = "B": X values print as degrees of B around a
+   cylinder of the job's wrap diameter (the X in [X]'s prefix becomes
+   B), Y prints as a length; arcs are linearized in the unrolled plane
+   first (the base has no arc sections);
+ - [WRAP_DIA] and [A] (the wrapped angle) in comments.
+
+================================================

POST_BASE = "gcode_noarcs_mm.pp"

POST_NAME = "G-Code no arcs, WrapX2B (mm) (*.nc)"

ROTARY_WRAP_X = "B"

VAR WRAP_DIAMETER = [WRAP_DIA|A||1.3]
VAR A_POSITION = [A|A||1.3]

begin HEADER
"%"
"O0200 ([TP_FILENAME] WRAPPED ON D[WRAP_DIA])"
"[N] G21 G90 G17 G40 G80"
"[N] (TOOL T[T] DIA [TDIA] [TOOLNAME] - [TOOL_NOTES])"
"[N] G91 G28 Z0"
"[N] G90 T[T] M6"
"[N] G43 H[T]"
"[N] G0[ZH]"

begin FOOTER
"[N] M5"
"[N] G91 G28 Z0"
"[N] (B AT [A] DEG)"
"[N] G90 G0 B0[YH]"
"[N] M30"
"%"

+================================================
+
+ postc library: HPGL plotters, vinyl and drag-knife cutters, mm.
+
+ Written for postc from the HP-GL reference: IN (initialize), SP1 (pen
+ 1), PA (absolute plotting), pen up (PU) for rapids and pen down (PD) for
+ feed moves, in plotter units of 0.025 mm (40 per mm). Arcs are AA with
+ the absolute centre and the sweep in degrees (counter-clockwise
+ positive; [Angle] is in radians, the multiplier turns it into degrees).
+ HPGL is two-dimensional: Z and feed rates are not written.
+
+ postc verify does not read HPGL: this post's output is checked by its
+ goldens (docs/posts.md).
+
+================================================

POST_NAME = "HPGL (mm) (*.plt)"
FILE_EXTENSION = "plt"
UNITS = "MM"
LINE_ENDING = "[13][10]"

VAR X_POSITION = [X|A||1.0|40]
VAR Y_POSITION = [Y|A||1.0|40]
VAR ARC_CENTRE_I_ABS_POSITION = [IA|A||1.0|40]
VAR ARC_CENTRE_J_ABS_POSITION = [JA|A||1.0|40]
VAR ARC_ANGLE = [Angle|A||1.3|57.2957795]
VAR X_HOME_POSITION = [XH|A||1.0|40]
VAR Y_HOME_POSITION = [YH|A||1.0|40]

begin HEADER
"IN;SP1;PA;"

begin RAPID_MOVE
"PU[X],[Y];"

begin FEED_MOVE
"PD[X],[Y];"

begin CW_ARC_MOVE
"PD;AA[IA],[JA],[Angle];"

begin CCW_ARC_MOVE
"PD;AA[IA],[JA],[Angle];"

begin FOOTER
"PU[XH],[YH];"
"SP0;"

+ Converted by postc from hpgl_arcs.pp (Vectric)
+================================================
+
+ postc: a generic HPGL plotter post with arcs, in the style of the
+ "Generic HPGL_Arcs.pp" the Vectric guide names. 40 plotter units per mm.
+ [Angle] is the arc sweep in radians (counter-clockwise positive); the
+ multiplier turns it into the degrees HPGL AA wants.
+
+================================================

POST_NAME = "Generic HPGL Arcs (*.plt)"

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

"IN;PA;"

begin RAPID_MOVE

"PU[X],[Y];"

begin FEED_MOVE

"PD[X],[Y];"

begin CW_ARC_MOVE

"AA[IA],[JA],[Angle]"

begin CCW_ARC_MOVE

"AA[IA],[JA],[Angle]"

begin FOOTER

"PU[XH],[YH];"
"SP0;"

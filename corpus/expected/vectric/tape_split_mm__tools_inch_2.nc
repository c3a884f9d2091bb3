( tools_inch.tap in C:\Jobs\Sign )
( path C:\Jobs\Sign )
G21 G90 G17 G40 G49 G94
G0Z38.100
T1 M6
G43 H1
( Finish: same tool, full depth )
( cut 2032 plunge 508 mm/min )
S14000 M3
G0X50.800Y50.800Z5.080
G1Z-12.700F508.0
G1X558.800F2032.0
G0Z5.080
M5
G0Z38.100
T2 M6
G43 H2
S16000 M3
( V-Carve: one stroke with a pause at the bottom )
( cut 1524 plunge 381 mm/min )
G0X304.800Y228.600Z5.080
G1Z-3.175F381.0
G4P0.75
G1X355.600Z-1.588F1524.0
G0Z5.080
M5
G0Z38.100
G0X0.000Y0.000
M30

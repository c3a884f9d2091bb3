( drill_mm.nc in /jobs/drill )
( path /jobs/drill )
G21 G90 G17 G40 G49 G94
G0Z20.000
T4 M6
G43 H4
( Spot holes: straight in, 1.25 s dwell; a 2 s dwell between the holes )
( cut 300 plunge 150 mm/min )
S6000 M3
G0X20.000Y40.000Z5.000
G0Z2.000
G1Z-2.000F150.0
G4P1.25
G0Z5.000
G0X30.000
G1Z-1.000
G4P2.00
G0Z5.000
G0X40.000
G0Z2.000
G1Z-2.000
G4P1.25
G0Z5.000
M5
G0Z20.000
G0X0.000Y0.000
M30

(BRACKET [REV B])
(check the clamps)
N5 M01

# crowd.awk: issue 35's crowds, 100 balls of radius 0.05 and elasticity 0.5 under
# gravity, each world closed at both ends by static walls (bench/run.sh; the
# grooves' rest is tested in tests/test_pressure.c):
#   awk -v kind=groove -v a=30 -v b=60 -f bench/crowd.awk > FILE.vroc
#     a V-groove of static faces rising at a and b degrees from the horizontal;
#   awk -v kind=slot -f bench/crowd.awk > FILE.vroc
#     a slot on a floor 1e-7 m wider than a ball, the balls in four layers in it;
#   -v friction=0 makes either world frictionless (the defaults' friction else).
BEGIN {
    pi = atan2(0, -1); L = 1.3
    if (friction == "0") print "default_friction = 0; default_rolling_friction = 0"
    if (kind == "groove") {
        ra = a * pi / 180; rb = b * pi / 180; W = 1; t = 0.05
        printf "cube face-a; mass = -1; size = (%.17g, %.17g, %.17g); rotate = (0, 1, 0) %.17g; translate = (%.17g, 0, %.17g)\n", W, L + 0.1, t, -ra, W * cos(ra) + t * sin(ra), W * sin(ra) - t * cos(ra)
        printf "cube face-b; mass = -1; size = (%.17g, %.17g, %.17g); rotate = (0, 1, 0) %.17g; translate = (%.17g, 0, %.17g)\n", W, L + 0.1, t, rb, -W * cos(rb) - t * sin(rb), W * sin(rb) - t * cos(rb)
        printf "cube end-n; mass = -1; size = (1.2, 0.05, 1.2); translate = (0, %.17g, 0.6)\n", L + 0.05
        printf "cube end-s; mass = -1; size = (1.2, 0.05, 1.2); translate = (0, %.17g, 0.6)\n", -L - 0.05
        for (k = 0; k < 4; k++) for (i = 0; i < 25; i++)
            printf "sphere b%d; radius = 0.05; elasticity = 0.5; translate = (%g, %.17g, %.17g)\n", n++, (k % 2 ? 0.03 : -0.03), -1.25 + i * 0.104, 0.35 + k * 0.12
    } else {
        h = 0.05 + 5e-8
        print "cube floor; mass = -1; size = (0.5, 1.5, 0.05); translate = (0, 0, -0.05)"
        printf "cube side-e; mass = -1; size = (0.05, 1.5, 1); translate = (%.17g, 0, 1)\n", h + 0.05
        printf "cube side-w; mass = -1; size = (0.05, 1.5, 1); translate = (%.17g, 0, 1)\n", -h - 0.05
        printf "cube end-n; mass = -1; size = (0.05, 0.05, 1); translate = (0, %.17g, 1)\n", L + 0.05
        printf "cube end-s; mass = -1; size = (0.05, 0.05, 1); translate = (0, %.17g, 1)\n", -L - 0.05
        for (k = 0; k < 4; k++) for (i = 0; i < 25; i++)
            printf "sphere b%d; radius = 0.05; elasticity = 0.5; translate = (0, %.17g, %.17g); velocity = (%g, 0, 0)\n", n++, -1.25 + i * 0.103 + (k % 2) * 0.01, 0.1 + k * 0.15, (i % 3 - 1) * 0.5
    }
    print "gravity"
}

# fuzzdict.awk: the AFL++ dictionary of vroc's language, from commands/.
#
#   awk -f tools/fuzzdict.awk commands/* > build-fuzz/vroc.dict
#
# Each file of commands/ is one command (the file's name is the word); its usage
# line gives the words that may follow it (on|off, pair|sbs|anaglyph|mono, ...).
# To those the dictionary adds the punctuation of the lexer, the words of
# expressions, and numbers at the edges of what a double and the value checks
# accept, so the fuzzer need not find them byte by byte.  POSIX awk.

function add(tok) {
    if (tok in seen) return
    seen[tok] = 1
    gsub(/\\/, "\\\\", tok)
    gsub(/"/, "\\\"", tok)
    gsub(/\n/, "\\x0a", tok)
    printf "tok_%d=\"%s\"\n", ++n, tok
}

FNR == 1 {
    name = FILENAME
    sub(/.*\//, "", name)
    add(name)
    add(name " = ")
    add("x." name " = ")
}

/^usage: / {
    line = substr($0, 8)
    k = split(line, w, /[][ ()=,]+/)
    for (i = 1; i <= k; i++) {
        if (w[i] !~ /\|/) continue
        m = split(w[i], alt, "|")
        for (j = 1; j <= m; j++) add(alt[j])
    }
}

END {
    split("( ) , = ; # \" . \\n (0, 0, 0) (1, 1, 1) off on", p, " ")
    for (i in p) add(p[i] == "\\n" ? "\n" : p[i])
    # expressions (expr.h): operators, constants, the unit, the functions
    split("+ - * / ^ pi e deg sqrt( sin( cos( tan( asin( acos( atan2( exp( log( abs( " \
          "min( max( 1/3 -2^2 30 deg", x, " ")
    for (i in x) add(x[i])
    split("0 1 -1 0.5 2 3 16 255 256 1000 1e9 1e-6 1e4 1e-9 1e308 -1e308 1e-320 5e-324 " \
          "1.7976931348623157e308 2.2250738585072014e-308 4294967295 4294967296 nan inf " \
          "-0 0x1p-1074 1e999 .5 9999999999", num, " ")
    for (i in num) add(num[i])
}

# mkhelp.awk: builds vroc's command reference from the files of commands/.
#
#   awk -f tools/mkhelp.awk -v mode=c commands/*            > build/gen/help_data.c
#   awk -f tools/mkhelp.awk -v mode=man -v template=man/vroc.1.in commands/* > man/vroc.1
#
# Each file commands/NAME describes the command or property NAME in five fields,
# always in this order:
#
#   group: object | property | system | console | view | sound
#   usage: one line, starting with NAME            (radius = r)
#   summary: one line, lower case, no final period
#   description:
#   paragraphs, a blank line between them; lines starting with two spaces are
#   kept verbatim (small tables)
#   example:
#   lines of the language
#
# mode=c writes the C table of help.h (sorted by name, byte order, so help_find
# can bisect with strcmp); mode=man copies the template, replacing the line
# `.\" @COMMANDS@` with one mdoc subsection per group.  A malformed file stops the
# build with a message naming it and a non-zero status.  POSIX awk only: runs with
# mawk and gawk and gives the same bytes with both.

BEGIN {
    split("group usage summary description example", field, " ")
    nfields = 5
    for (gk = 1; gk <= nfields; gk++)
        fieldno[field[gk]] = gk
    ngroups = split("object property system console view sound", groupname, " ")
    split("Objects|Object properties|System commands|Console commands|Views and hand|Sound and movies",
          grouptitle, "|")
    for (gk = 1; gk <= ngroups; gk++)
        isgroup[groupname[gk]] = 1
    for (gk = 32; gk < 127; gk++)
        ord[sprintf("%c", gk)] = gk
    failed = 0
    n = 0          # entries read
    file = ""      # file being read
    if (mode != "c" && mode != "man")
        die("", 0, "mode must be c or man (got '" mode "')")
    if (mode == "man" && template == "")
        die("", 0, "mode=man needs -v template=FILE")
}

# Prints "mkhelp: FILE:LINE: MSG" on standard error and stops with status 1.
function die(f, line, msg,    where) {
    where = f == "" ? "" : (line > 0 ? f ":" line ": " : f ": ")
    print "mkhelp: " where msg | "cat 1>&2"
    close("cat 1>&2")
    failed = 1
    exit 1
}

# Byte-order comparison of two ASCII strings: <0, 0 or >0, like strcmp.
function bytecmp(a, b,    i, la, lb, ca, cb) {
    la = length(a); lb = length(b)
    for (i = 1; i <= la && i <= lb; i++) {
        ca = ord[substr(a, i, 1)]; cb = ord[substr(b, i, 1)]
        if (ca != cb)
            return ca - cb
    }
    return la - lb
}

function basename(path) {
    sub(/.*\//, "", path)
    return path
}

# Starts reading the file f.
function begin_file(f) {
    file = f
    name = basename(f)
    if (name !~ /^[a-z][a-z0-9_]*$/)
        die(f, 0, "file name must be a command word: lower case letters, digits, _")
    if (name in seen)
        die(f, 0, "command '" name "' is described twice")
    seen[name] = 1
    seenfile[f] = 1
    nf = 0
    section = ""
    val["group"] = val["usage"] = val["summary"] = ""
    ndesc = nex = 0
}

# Checks the file just read and stores its entry.
function end_file(    i, j, t, text, first, prevblank, d) {
    if (nf < nfields)
        die(file, 0, "missing field '" field[nf + 1] ":'")
    if (!(val["group"] in isgroup))
        die(file, 0, "unknown group '" val["group"] \
            "' (object, property, system, console or view)")
    split(val["usage"], t, " ")
    if (t[1] != name)
        die(file, 0, "usage must start with the command word '" name "'")
    if (val["summary"] !~ /^[a-z]/)
        die(file, 0, "summary must start with a lower case letter")
    if (val["summary"] ~ /\.$/)
        die(file, 0, "summary must not end with a period")
    # description: drop blank lines at both ends and repeated blank lines
    text = ""; first = 1; prevblank = 0
    for (i = 1; i <= ndesc; i++) {
        if (desc[i] == "") {
            prevblank = 1
            continue
        }
        if (!first)
            text = text (prevblank ? "\n\n" : "\n")
        text = text desc[i]
        first = 0; prevblank = 0
    }
    if (text == "")
        die(file, 0, "empty description")
    d = text
    # example: drop blank lines at both ends
    i = 1; j = nex
    while (i <= j && ex[i] == "") i++
    while (j >= i && ex[j] == "") j--
    if (i > j)
        die(file, 0, "empty example")
    text = ex[i]
    for (i++; i <= j; i++)
        text = text "\n" ex[i]
    n++
    E_desc[n] = d
    E_ex[n] = text
    E_name[n] = name
    E_group[n] = val["group"]
    E_usage[n] = val["usage"]
    E_summary[n] = val["summary"]
    E_mdoc[n] = usage_mdoc(val["usage"])
    file = ""
}

# A new file: finish the one before.
FNR == 1 {
    if (file != "")
        end_file()
    begin_file(FILENAME)
}

# Every line: a field, or a line of the description or the example.
{
    cur = $0
    if (cur ~ /\r/)
        die(file, FNR, "carriage return (save the file with Unix line ends)")
    if (cur ~ /\t/)
        die(file, FNR, "tab character (use spaces)")
    if (cur ~ /[^ -~]/)
        die(file, FNR, "character outside printable ASCII")
    sub(/ +$/, "", cur)
    if (cur ~ /^(group|usage|summary|description|example):/) {
        fname = cur
        sub(/:.*/, "", fname)
        value = cur
        sub(/^[a-z]+: */, "", value)
        if (nf == nfields)
            die(file, FNR, "field '" fname ":' after 'example:'")
        if (fieldno[fname] > nf + 1)
            die(file, FNR, "missing field '" field[nf + 1] ":' before '" fname ":'")
        if (fieldno[fname] < nf + 1)
            die(file, FNR, "field '" fname ":' out of order or repeated " \
                "(expected '" field[nf + 1] ":')")
        nf++
        section = fname
        if (section == "description" || section == "example") {
            if (value != "")
                die(file, FNR, "text after '" fname ":' (start it on the next line)")
        } else {
            if (value == "")
                die(file, FNR, "empty field '" fname ":'")
            val[section] = value
        }
        next
    }
    if (section == "")
        die(file, FNR, "text before 'group:'")
    if (section == "description") {
        if (cur ~ /^ [^ ]/)
            die(file, FNR, "line starts with one space (two mark a verbatim line)")
        desc[++ndesc] = cur
    } else if (section == "example") {
        ex[++nex] = cur
    } else if (cur != "") {
        die(file, FNR, "'" section ":' must be one line")
    }
}

# Escapes s for a C string literal: backslash, double quote, and ? (no trigraphs).
function cstr(s) {
    s = replace(s, "\\", "\\\\")
    s = replace(s, "\"", "\\\"")
    s = replace(s, "?", "\\?")
    s = replace(s, "\n", "\\n")
    return "\"" s "\""
}

# s with every from replaced by to, both literal (gsub's handling of backslashes
# in the replacement differs between awks).
function replace(s, from, to,    out, k, lf) {
    out = ""
    lf = length(from)
    while ((k = index(s, from)) > 0) {
        if (k > 1)
            out = out substr(s, 1, k - 1)
        out = out to
        s = k + lf <= length(s) ? substr(s, k + lf) : ""
    }
    return out s
}

# A multi-line text as adjacent C literals, one per line, each but the last
# ending in \n (keeps every literal short: -Woverlength-strings).
function clines(s, indent,    k, i, ln, out) {
    k = split(s, ln, "\n")
    out = ""
    for (i = 1; i <= k; i++) {
        out = out (i > 1 ? "\n" indent : "") cstr(ln[i] (i < k ? "\n" : ""))
    }
    return out
}

# Escapes a text line for mdoc: backslashes, and a leading . or ' (control lines).
function mtext(s) {
    s = replace(s, "\\", "\\e")
    s = replace(s, "\001", "\\~")
    if (s ~ /^[.']/)
        s = "\\&" s
    return s
}

# A word as a macro argument: a word that looks like a macro name is escaped.
function marg(s) {
    s = mtext(s)
    if (s ~ /^[A-Z][a-z][a-z]?$/ || s ~ /^%[A-Z]$/)
        s = "\\&" s
    return s
}

# The usage line as the arguments of an mdoc .It: the command word with Ic, = with
# Li, alternatives a|b with Cm, [..] with Op (joined with Ns to the word before
# when written against it: NAME[.property]), vectors and placeholders with Ar.
function usage_mdoc(u,    t, k, i, out, mac, alt, na, j, glued) {
    glued = u ~ /[^ ]\[/
    gsub(/\(/, " ( ", u); gsub(/\)/, " ) ", u); gsub(/,/, " , ", u)
    gsub(/\[/, " [ ", u); gsub(/\]/, " ] ", u)
    k = split(u, t, " ")
    out = "Ic " marg(t[1])
    mac = "Ic"
    for (i = 2; i <= k; i++) {
        if (t[i] == "[") {
            if (mac == "Op")
                die(file, 0, "nested [ in usage")
            out = out (glued ? " Ns" : "") " Op"; mac = "Op"
        } else if (t[i] == "]") {
            if (i != k)
                die(file, 0, "] must end the usage line")
        } else if (t[i] == "=") {
            out = out " Li ="; mac = "Li"
        } else if (t[i] ~ /\|/) {
            na = split(t[i], alt, "|")
            out = out " Cm"
            for (j = 1; j <= na; j++) {
                if (alt[j] !~ /^[a-z0-9_]+$/)
                    die(file, 0, "bad alternative '" alt[j] "' in usage")
                out = out (j > 1 ? " |" : "") " " marg(alt[j])
            }
            mac = "Cm"
        } else if (t[i] == "(" || t[i] == ")" || t[i] == ",") {
            if (mac != "Ar")
                out = out " Ar"
            out = out " " t[i]; mac = "Ar"
        } else if (t[i] ~ /^\.?[A-Za-z_][A-Za-z0-9_]*$/) {
            if (mac != "Ar")
                out = out " Ar"
            out = out " " marg(t[i]); mac = "Ar"
        } else {
            die(file, 0, "cannot read '" t[i] "' in usage")
        }
    }
    return out
}

function emit_c(    i) {
    print "/* help_data.c: the command reference, generated by tools/mkhelp.awk from"
    print " * commands/.  Do not edit: edit the files of commands/ instead. */"
    print "#include \"shell/help.h\""
    print ""
    print "#include <string.h>"
    print ""
    print "const help_entry help_entries[] = {"
    for (i = 1; i <= n; i++) {
        print "    {" cstr(E_name[i]) ", " cstr(E_group[i]) ", " cstr(E_usage[i]) ","
        print "     " cstr(E_summary[i]) ","
        print "     " clines(E_desc[i], "     ") ","
        print "     " clines(E_ex[i], "     ") "},"
    }
    print "};"
    print ""
    print "const int help_count = " n ";"
    print ""
    print "const help_entry *help_find(const char *name)"
    print "{"
    print "    int lo = 0, hi = help_count - 1;"
    print "    if (name == NULL)"
    print "        return NULL;"
    print "    while (lo <= hi) {"
    print "        int mid = lo + (hi - lo) / 2;"
    print "        int c = strcmp(name, help_entries[mid].name);"
    print "        if (c == 0)"
    print "            return &help_entries[mid];"
    print "        if (c < 0)"
    print "            hi = mid - 1;"
    print "        else"
    print "            lo = mid + 1;"
    print "    }"
    print "    return NULL;"
    print "}"
}

# s with the spaces that should not break a line marked by \001 (mtext turns
# them into \~): those inside a short group in parentheses with a digit or a
# comma, such as a vector (0, 0, 1), and those after a comparison, as in
# "a number > 0".
function nobreak(s,    out, grp, rest) {
    out = ""
    while (match(s, /\([^()]*\)/)) {
        grp = substr(s, RSTART, RLENGTH)
        if (RLENGTH <= 24 && grp ~ /[0-9,]/)
            gsub(/ /, "\001", grp)
        if (RSTART > 1)
            out = out substr(s, 1, RSTART - 1)
        out = out grp
        rest = RSTART + RLENGTH
        s = rest <= length(s) ? substr(s, rest) : ""
    }
    s = out s
    s = replace(s, " >= ", " >=\001")
    s = replace(s, " <= ", " <=\001")
    s = replace(s, " > ", " >\001")
    s = replace(s, " < ", " <\001")
    return s
}

# Prints a paragraph of text as mdoc text lines, one sentence per line
# (mandoc wants each sentence to start a line).
function man_para(s,    sent) {
    s = nobreak(s)
    while (match(s, /[.!?][])"']* +/)) {
        sent = substr(s, 1, RSTART + RLENGTH - 1)
        sub(/ +$/, "", sent)
        print mtext(sent)
        s = substr(s, RSTART + RLENGTH)
    }
    if (s != "")
        print mtext(s)
}

# One entry of the mdoc command list: the usage as the tag, then the summary
# as a sentence, the description (verbatim lines as literal displays) and the
# example as a literal display.
function emit_man_entry(i,    k, ln, j, s, para, inblock, pendpp) {
    print ".It " E_mdoc[i]
    s = E_summary[i]
    print mtext(toupper(substr(s, 1, 1)) substr(s, 2) ".")
    k = split(E_desc[i], ln, "\n")
    inblock = 0; pendpp = 0; para = ""
    for (j = 1; j <= k; j++) {
        if (ln[j] == "") {
            man_para(para); para = ""
            pendpp = 1
        } else if (ln[j] ~ /^  /) {
            man_para(para); para = ""
            if (!inblock)
                print ".Bd -literal -offset indent"
            inblock = 1; pendpp = 0
            print mtext(substr(ln[j], 3))
        } else {
            if (inblock)
                print ".Ed"
            if (pendpp)
                print ".Pp"
            inblock = 0; pendpp = 0
            para = para (para == "" ? "" : " ") ln[j]
        }
    }
    man_para(para)
    if (inblock)
        print ".Ed"
    print ".Bd -literal -offset indent"
    k = split(E_ex[i], ln, "\n")
    for (j = 1; j <= k; j++)
        print mtext(ln[j])
    print ".Ed"
}

function emit_man(    g, i, any, line, r, done) {
    done = 0
    while ((r = (getline line < template)) > 0) {
        if (line != ".\\\" @COMMANDS@") {
            print line
            continue
        }
        if (done)
            die(template, 0, "the line .\\\" @COMMANDS@ appears twice")
        done = 1
        for (g = 1; g <= ngroups; g++) {
            any = 0
            for (i = 1; i <= n; i++) {
                if (E_group[i] != groupname[g])
                    continue
                if (!any) {
                    print ".Ss " grouptitle[g]
                    print ".Bl -tag -width Ds"
                    any = 1
                }
                emit_man_entry(i)
            }
            if (any)
                print ".El"
        }
    }
    if (r < 0)
        die(template, 0, "cannot read the template")
    close(template)
    if (!done)
        die(template, 0, "no line .\\\" @COMMANDS@ to replace")
}

END {
    if (failed)
        exit 1
    if (file != "")
        end_file()
    # An empty file gives awk no line, so it is caught here.
    for (gk = 1; gk < ARGC; gk++) {
        if (ARGV[gk] == "" || ARGV[gk] ~ /^[A-Za-z_][A-Za-z0-9_]*=/)
            continue
        if (!(ARGV[gk] in seenfile))
            die(ARGV[gk], 0, "empty file")
    }
    if (n == 0)
        die("", 0, "no command files given")
    # insertion sort by name, byte order
    for (gk = 2; gk <= n; gk++) {
        for (gm = gk; gm > 1 && bytecmp(E_name[gm - 1], E_name[gm]) > 0; gm--) {
            swap(gm - 1, gm)
        }
    }
    if (mode == "c")
        emit_c()
    else
        emit_man()
}

function swap(a, b,    t) {
    t = E_name[a]; E_name[a] = E_name[b]; E_name[b] = t
    t = E_group[a]; E_group[a] = E_group[b]; E_group[b] = t
    t = E_usage[a]; E_usage[a] = E_usage[b]; E_usage[b] = t
    t = E_summary[a]; E_summary[a] = E_summary[b]; E_summary[b] = t
    t = E_desc[a]; E_desc[a] = E_desc[b]; E_desc[b] = t
    t = E_ex[a]; E_ex[a] = E_ex[b]; E_ex[b] = t
    t = E_mdoc[a]; E_mdoc[a] = E_mdoc[b]; E_mdoc[b] = t
}

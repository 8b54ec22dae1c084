// str_precision: a negative precision of str() and vstr() is printf's default, however large
// (fuzz_parse, built by clang with UBSan, found the conversion to int overflowing).
#debug concat(str(2.5, 0, -1e300), " ", vstr(2, <1, 2>, ",", 0, -3e15), "\n")
sphere { 0, 1 }

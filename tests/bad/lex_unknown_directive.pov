#foo 1

// messages: #debug writes its text as it is to stderr ("\n" ends a line), #warning reports a
// warning at its place, #undef of an unknown name warns; a skipped #error does not run.
// tests/lang/check_cli.sh compares the stderr with messages.stderr.
#declare Msg = "from a name\n";
#debug "debug: one, "
#debug "two\tparts\n"
#debug Msg
#warning "a warning\n"
#undef Nothing
#if (0) #error "skipped" #end
sphere { 0, 1 }

// charset takes ascii, utf8 or sys.
global_settings { charset latin1 }

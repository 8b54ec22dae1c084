global_settings { max_trace_level 2.5 }

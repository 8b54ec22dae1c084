global_settings { photons { count 1000 } }

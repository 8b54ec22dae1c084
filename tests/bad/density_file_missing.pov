// a density file that is not there
sphere { 0, 1 pigment { density_file df3 "nowhere.df3" } }

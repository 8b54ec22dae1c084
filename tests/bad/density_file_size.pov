// a df3 whose length fits no voxel size
sphere { 0, 1 pigment { density_file df3 "short.df3" } }

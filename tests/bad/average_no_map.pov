// average needs the entries it averages.
sphere { 0, 1 pigment { average } }

#declare G = <1, 2>.gray;

#declare R = rand(3);

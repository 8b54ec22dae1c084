#declare V = vnormalize(<0, 0, 0>);

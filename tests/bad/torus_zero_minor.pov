torus { 1, 0 sturm }

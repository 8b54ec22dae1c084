media { scattering { 1, rgb 0.02 } }

media { absorption 0.1 }
media { scattering { 1 } }

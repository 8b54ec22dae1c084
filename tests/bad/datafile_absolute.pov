// An absolute path outside the scene's folder and the -I folders is refused too.
#fopen F "/etc/hostname" read

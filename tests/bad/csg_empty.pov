intersection {
}

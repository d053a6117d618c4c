float f(float a) {
  return a +* 2.0;
}

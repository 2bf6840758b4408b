// railfe-contact-search-benchmark: placeholder until the timing driver lands.
int main() {
  return 0;
}

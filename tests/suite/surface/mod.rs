mod displaced;
